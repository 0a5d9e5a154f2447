//! \example tutorial-ssl-target-generator.cpp
//! Writes a printable target: a 1:1 vector PDF and SVG and a PNG of the sheet, with the target's name,
//! the landmark radii and a 100 mm scale bar in the margin (doc/target-ssl3-a3.md, "Printing").
//!
//! Each circular landmark (paper Fig. 1b, Eq. 4) is drawn as exact vector discs, from the outside in,
//! each disc coloured by vpSSLPattern: the disc of radius R p^(k/2) carries the colour of ring k, so the
//! next, smaller disc leaves a ring of width R p^(k/2) (1 - sqrt(p)). Rings thinner than --min-ring-mm
//! (default 0.1 mm, about a printer's resolution) are not drawn: the last disc drawn reaches the centre,
//! which therefore has the colour of the innermost drawn ring. --linear draws instead the original
//! linear landmark of Briggs et al. (paper Fig. 1a), the same square wave along X, constant along Y.
//!
//! Sheet coordinates are the target frame: X right, Y down as seen from the printed side.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <dlfcn.h>

#include <visp3/core/vpException.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/ssl/vpSSLPattern.h>
#include <visp3/ssl/vpSSLTarget.h>

namespace {
const double kPointsPerMetre = 72. / 0.0254; // PDF and SVG user unit: the point, 1/72 inch
const double kMm = 1e-3;
const double kEdgeMargin = 8 * kMm; // most printers cannot print the outer 3-6 mm of a sheet
const double kClearance = 3 * kMm;  // between text and a landmark or another block
const double kTextSize = 3.2 * kMm; // about 9 pt
const double kTitleSize = 6 * kMm;

// The linear landmark of --linear (paper Fig. 1a), centred on an A4 landscape sheet.
const double kLinearLength = 0.200, kLinearHeight = 0.100, kA4Width = 0.297, kA4Height = 0.210;

struct Options
{
  std::string target = "ssl3-a3";
  bool targetGiven = false;
  std::string output;
  int dpi = 150;
  bool linear = false;
  double minRingMm = 0.1;
};

void printHelp(const char *prog)
{
  std::cout << "Usage: " << prog << " [options]\n"
            << "Writes a printable self-similar landmark target: PREFIX.pdf and PREFIX.svg (vector, 1:1 scale)\n"
            << "and PREFIX.png. Print the PDF at 100 % / actual size (no \"fit to page\") and check the 100 mm bar.\n\n"
            << "Options:\n"
            << "  --target NAME_OR_FILE  built-in target name (ssl3-a3) or a target file (doc/target-file.md).\n"
            << "                         Default: ssl3-a3.\n"
            << "  --output PREFIX        output files PREFIX.pdf, PREFIX.svg, PREFIX.png (the folder of PREFIX\n"
            << "                         is made if it does not exist).\n"
            << "                         Default: the target's name (ssl3-a3), or ssl-linear with --linear.\n"
            << "  --dpi N                resolution of the PNG in dots per inch, 10 to 600; the PNG holds 1 to\n"
            << "                         32767 px a side and at most 2^27 px. Default: 150.\n"
            << "  --linear               draw instead the original linear landmark of Briggs et al. (paper Fig. 1a):\n"
            << "                         the square wave along X, constant along Y, 200 mm x 100 mm, A4 landscape.\n"
            << "                         Cannot be combined with --target.\n"
            << "  --min-ring-mm X        rings (or stripes) thinner than X mm are not drawn; the centre then has the\n"
            << "                         colour of the innermost ring drawn. Default: 0.1 (about a printer's dot).\n"
            << "  --help                 print this help and exit.\n\n"
            << "Exit status: 0 on success, 2 on a bad option or target file (nothing written; limits in\n"
            << "doc/target-file.md), 1 when an output cannot be written or on any other runtime failure (one\n"
            << "line on stderr).\n\n"
            << "Sheet coordinates are the target frame: X right, Y down, seen from the printed side.\n"
            << "The name, radii and scale bar go where the sheet has room; a label that fits nowhere is left out\n"
            << "with a warning on stderr.\n";
}

double parseNumber(const std::string &option, const std::string &text)
{
  size_t used = 0;
  double v = 0.;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v)) {
    throw std::runtime_error(option + ": not a number: \"" + text + "\"");
  }
  return v;
}

Options parseOptions(int argc, char **argv, bool &help)
{
  Options o;
  help = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        throw std::runtime_error(a + ": missing value (see --help)");
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      help = true;
    } else if (a == "--target") {
      o.target = value();
      o.targetGiven = true;
    } else if (a == "--output") {
      o.output = value();
      if (o.output.empty()) {
        throw std::runtime_error("--output: empty prefix");
      }
    } else if (a == "--dpi") {
      std::string t = value();
      double d = parseNumber(a, t);
      if (d != std::floor(d) || d < 10 || d > 600) {
        throw std::runtime_error("--dpi: must be an integer in [10, 600], got \"" + t + "\"");
      }
      o.dpi = static_cast<int>(d);
    } else if (a == "--linear") {
      o.linear = true;
    } else if (a == "--min-ring-mm") {
      std::string t = value();
      o.minRingMm = parseNumber(a, t);
      if (!(o.minRingMm > 0.)) {
        throw std::runtime_error("--min-ring-mm: must be > 0, got \"" + t + "\"");
      }
    } else {
      throw std::runtime_error("unknown option \"" + a + "\" (see --help)");
    }
  }
  if (o.linear && o.targetGiven) {
    throw std::runtime_error("--linear and --target cannot be combined");
  }
  return o;
}

// Axis-aligned rectangle in the target frame (m).
struct Rect
{
  double x0, y0, x1, y1;
  Rect grown(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
  bool overlaps(const Rect &o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool inside(const Rect &o) const { return x0 >= o.x0 && x1 <= o.x1 && y0 >= o.y0 && y1 <= o.y1; }
  bool overlapsDisc(double cx, double cy, double r) const
  {
    double dx = cx - std::clamp(cx, x0, x1), dy = cy - std::clamp(cy, y0, y1);
    return dx * dx + dy * dy < r * r;
  }
};

struct TextLine
{
  std::string text;
  double size;
  bool bold;
};

// A block of text lines, optionally followed by the 100 mm scale bar; placed by layout().
struct Block
{
  std::vector<TextLine> lines;
  bool scaleBar = false;
  double w = 0., h = 0.;
  double x = 0., y = 0.; // top-left corner once placed
  bool placed = false;
};

// Everything printed on the sheet, in the target frame.
struct Page
{
  std::string name;
  Rect sheet;
  std::vector<vpSSLTargetLandmark> discs; // circular landmarks
  bool linear = false;
  Rect linearRect{0, 0, 0, 0};
  double linearP = 0.5;
  double minRing = 0.1 * kMm;
  std::vector<Block> blocks;
};

const double kScaleBarHeight = 9 * kMm; // tick labels, bar and its caption

void setFont(cairo_t *cr, double size, bool bold)
{
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double textWidth(cairo_t *cr, const TextLine &l)
{
  setFont(cr, l.size, l.bold);
  cairo_text_extents_t e;
  cairo_text_extents(cr, l.text.c_str(), &e);
  return e.x_advance;
}

void measure(cairo_t *cr, Block &b)
{
  b.w = b.scaleBar ? 100 * kMm + 2 * kMm : 0.;
  b.h = b.scaleBar ? kScaleBarHeight : 0.;
  for (const TextLine &l : b.lines) {
    b.w = std::max(b.w, textWidth(cr, l));
    b.h += 1.45 * l.size;
  }
}

// True when the rectangle keeps clear of the landmarks, the blocks already placed and the sheet edge.
bool isFree(const Page &page, const Rect &r)
{
  Rect printable{page.sheet.x0 + kEdgeMargin, page.sheet.y0 + kEdgeMargin, page.sheet.x1 - kEdgeMargin,
                 page.sheet.y1 - kEdgeMargin};
  if (!r.inside(printable)) {
    return false;
  }
  Rect g = r.grown(kClearance);
  for (const vpSSLTargetLandmark &d : page.discs) {
    if (g.overlapsDisc(d.x, d.y, d.radius)) {
      return false;
    }
  }
  if (page.linear && g.overlaps(page.linearRect)) {
    return false;
  }
  for (const Block &b : page.blocks) {
    if (b.placed && g.overlaps(Rect{b.x, b.y, b.x + b.w, b.y + b.h})) {
      return false;
    }
  }
  return true;
}

// Puts each block in the first free corner of the sheet, else at the first free place scanning the
// sheet row by row. A block that fits nowhere is left out with a warning: text over the rings would
// spoil the pattern, while the PDF stays 1:1 without its scale bar.
void layout(cairo_t *cr, Page &page)
{
  const Rect &s = page.sheet;
  // A 2 mm grid, coarser on a sheet over 2 m so that the scan stays within 1000 x 1000 places (a 100 m sheet
  // at 2 mm took 37 s and 4 GB); the places are visited, not stored.
  const double step = std::max(2 * kMm, std::max(s.x1 - s.x0, s.y1 - s.y0) / 1000.);
  for (Block &b : page.blocks) {
    measure(cr, b);
    double xl = s.x0 + kEdgeMargin, xr = s.x1 - kEdgeMargin - b.w;
    double yt = s.y0 + kEdgeMargin, yb = s.y1 - kEdgeMargin - b.h;
    auto tryPlace = [&](double x, double y) {
      if (isFree(page, Rect{x, y, x + b.w, y + b.h})) {
        b.x = x;
        b.y = y;
        b.placed = true;
      }
      return b.placed;
    };
    if (!tryPlace(xl, yt) && !tryPlace(xl, yb) && !tryPlace(xr, yt) && !tryPlace(xr, yb)) {
      const int nx = xr >= xl ? static_cast<int>(std::floor((xr - xl) / step)) : -1;
      const int ny = yb >= yt ? static_cast<int>(std::floor((yb - yt) / step)) : -1;
      for (int j = 0; j <= ny && !b.placed; ++j) {
        for (int i = 0; i <= nx && !tryPlace(xl + i * step, yt + j * step); ++i) {
        }
      }
    }
    if (!b.placed) {
      std::cerr << "warning: no room on the sheet for the text \"" << b.lines.front().text
                << "\": not printed (enlarge the sheet)" << std::endl;
    }
  }
  // A name tag next to each disc, on the side facing away from the other landmarks when possible;
  // the legend lists the radii anyway, so a tag that fits nowhere is dropped.
  double gx = 0., gy = 0.;
  for (const vpSSLTargetLandmark &d : page.discs) {
    gx += d.x / page.discs.size();
    gy += d.y / page.discs.size();
  }
  for (const vpSSLTargetLandmark &d : page.discs) {
    Block tag;
    std::ostringstream os;
    os.setf(std::ios::fixed);
    os.precision(1);
    os << d.name << "  R = " << d.radius / kMm << " mm";
    tag.lines.push_back({os.str(), kTextSize, true});
    measure(cr, tag);
    double ux = d.x - gx, uy = d.y - gy;
    const double gap = kClearance + 0.5 * kMm;
    struct Candidate
    {
      double dx, dy, x, y;
    };
    std::vector<Candidate> c = {{0, -1, d.x - 0.5 * tag.w, d.y - d.radius - gap - tag.h},
                                {0, 1, d.x - 0.5 * tag.w, d.y + d.radius + gap},
                                {1, 0, d.x + d.radius + gap, d.y - 0.5 * tag.h},
                                {-1, 0, d.x - d.radius - gap - tag.w, d.y - 0.5 * tag.h}};
    std::stable_sort(c.begin(), c.end(), [&](const Candidate &a, const Candidate &b) {
      return a.dx * ux + a.dy * uy > b.dx * ux + b.dy * uy;
    });
    for (const Candidate &k : c) {
      if (isFree(page, Rect{k.x, k.y, k.x + tag.w, k.y + tag.h})) {
        tag.x = k.x;
        tag.y = k.y;
        tag.placed = true;
        page.blocks.push_back(tag);
        break;
      }
    }
  }
}

void drawScaleBar(cairo_t *cr, double x, double y)
{
  // Ticks every 10 mm, long ones at 0, 50 and 100 mm, so that a rescaled print shows at a glance.
  const double barY = y + 6 * kMm;
  cairo_set_line_width(cr, 0.3 * kMm);
  cairo_move_to(cr, x, barY);
  cairo_line_to(cr, x + 100 * kMm, barY);
  for (int i = 0; i <= 10; ++i) {
    double len = (i % 5 == 0) ? 3 * kMm : 1.5 * kMm;
    cairo_move_to(cr, x + i * 10 * kMm, barY);
    cairo_line_to(cr, x + i * 10 * kMm, barY - len);
  }
  cairo_stroke(cr);
  setFont(cr, kTextSize, false);
  const char *labels[3] = {"0", "50", "100 mm"};
  for (int i = 0; i < 3; ++i) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, labels[i], &e);
    double lx = x + i * 50 * kMm - (i == 0 ? 0. : (i == 1 ? 0.5 : 1.) * e.x_advance);
    cairo_move_to(cr, lx, barY - 3.5 * kMm);
    cairo_show_text(cr, labels[i]);
  }
  cairo_move_to(cr, x, barY + 3 * kMm);
  cairo_show_text(cr, "scale bar: 100 mm when printed at actual size");
}

void drawBlock(cairo_t *cr, const Block &b)
{
  cairo_set_source_rgb(cr, 0, 0, 0);
  double y = b.y;
  for (const TextLine &l : b.lines) {
    y += 1.45 * l.size;
    setFont(cr, l.size, l.bold);
    cairo_move_to(cr, b.x, y - 0.4 * l.size);
    cairo_show_text(cr, l.text.c_str());
  }
  if (b.scaleBar) {
    drawScaleBar(cr, b.x + 1 * kMm, y);
  }
}

void fillColour(cairo_t *cr, int s)
{
  cairo_set_source_rgb(cr, s, s, s);
} // 0 black, 1 white

// Number of rings (or stripes) of a pattern of outer size `size` at least `minRing` wide; the
// outermost one is always drawn.
int ringCount(double size, double p, double minRing)
{
  const double q = std::sqrt(p);
  int k = 1;
  for (double r = size * q; k < 1000 && r * (1. - q) >= minRing; r *= q) {
    ++k;
  }
  return k;
}

// Rings from the outside in; ring k spans (R p^((k+1)/2), R p^(k/2)] (Eq. 1 and 4).
void drawCircular(cairo_t *cr, const vpSSLTargetLandmark &d, double minRing)
{
  const double q = std::sqrt(d.p);
  const int n = ringCount(d.radius, d.p, minRing);
  double r = d.radius;
  for (int k = 0; k < n; ++k, r *= q) {
    fillColour(cr, vpSSLPattern::circular(0.5 * (1. + q) * r, 0., d.radius, d.p));
    cairo_new_path(cr);
    cairo_arc(cr, d.x, d.y, r, 0., 2. * M_PI);
    cairo_fill(cr);
  }
}

// Stripes from the far end in; the pattern's abscissa starts at the rectangle's left edge. Each stripe
// is filled on its own (white ones are the paper) so that no antialiased edge is painted twice, which
// would leave grey hairlines along the long sides of the stripes.
void drawLinear(cairo_t *cr, const Rect &rect, double p, double minRing)
{
  const double q = std::sqrt(p), length = rect.x1 - rect.x0;
  const int n = ringCount(length, p, minRing);
  double a = length;
  for (int k = 0; k < n; ++k, a *= q) {
    double inner = (k + 1 < n) ? a * q : 0.; // the last stripe drawn reaches the pattern's origin
    if (vpSSLPattern::linear(0.5 * (1. + q) * a, length, p) == 0) {
      fillColour(cr, 0);
      cairo_new_path(cr);
      cairo_rectangle(cr, rect.x0 + inner, rect.y0, a - inner, rect.y1 - rect.y0);
      cairo_fill(cr);
    }
  }
}

void drawPage(cairo_t *cr, const Page &page, double unitsPerMetre)
{
  cairo_scale(cr, unitsPerMetre, unitsPerMetre);
  cairo_translate(cr, -page.sheet.x0, -page.sheet.y0);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, page.sheet.x0, page.sheet.y0, page.sheet.x1 - page.sheet.x0, page.sheet.y1 - page.sheet.y0);
  cairo_fill(cr);
  for (const vpSSLTargetLandmark &d : page.discs) {
    drawCircular(cr, d, page.minRing);
  }
  if (page.linear) {
    drawLinear(cr, page.linearRect, page.linearP, page.minRing);
  }
  for (const Block &b : page.blocks) {
    if (b.placed) {
      drawBlock(cr, b);
    }
  }
}

// Same glyph metrics on every surface, so that the layout made once fits all three outputs.
cairo_t *createContext(cairo_surface_t *surface)
{
  cairo_t *cr = cairo_create(surface);
  cairo_font_options_t *fo = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  cairo_set_font_options(cr, fo);
  cairo_font_options_destroy(fo);
  return cr;
}

void finish(cairo_surface_t *surface, cairo_t *cr, const std::string &filename)
{
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  if (st == CAIRO_STATUS_SUCCESS) {
    st = cairo_surface_status(surface);
  }
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(filename + ": cannot write: " + cairo_status_to_string(st));
  }
}

void writeVector(const Page &page, const std::string &filename, bool pdf)
{
  double w = (page.sheet.x1 - page.sheet.x0) * kPointsPerMetre, h = (page.sheet.y1 - page.sheet.y0) * kPointsPerMetre;
  cairo_surface_t *s =
      pdf ? cairo_pdf_surface_create(filename.c_str(), w, h) : cairo_svg_surface_create(filename.c_str(), w, h);
  if (pdf) {
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, page.name.c_str());
  } else {
    cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_PT); // 1 user unit = 1 pt: prints 1:1
  }
  cairo_t *cr = createContext(s);
  drawPage(cr, page, kPointsPerMetre);
  cairo_show_page(cr);
  finish(s, cr, filename);
}

// The PNG's size at dpi. Cairo's image surfaces hold 1 to 32767 pixels a side (beyond, "cannot write: invalid
// value"), and the surface takes 4 bytes a pixel: 2^27 pixels (512 MB) holds an A2 sheet at 600 dpi.
void pngSize(const Page &page, int dpi, int &width, int &height)
{
  const double pxPerMetre = dpi / 0.0254;
  const double w = std::round((page.sheet.x1 - page.sheet.x0) * pxPerMetre);
  const double h = std::round((page.sheet.y1 - page.sheet.y0) * pxPerMetre);
  if (!(w >= 1. && h >= 1. && w <= 32767. && h <= 32767. && w * h <= 134217728.)) {
    std::ostringstream os;
    os << "the sheet (" << (page.sheet.x1 - page.sheet.x0) / kMm << " x " << (page.sheet.y1 - page.sheet.y0) / kMm
       << " mm) is " << w << " x " << h << " px at " << dpi
       << " dpi; the PNG holds 1 to 32767 px a side and at most 2^27 px: change --dpi or the sheet";
    throw std::runtime_error(os.str());
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
}

void writePng(const Page &page, const std::string &filename, int dpi, int &width, int &height)
{
  const double pxPerMetre = dpi / 0.0254;
  pngSize(page, dpi, width, height);
  cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t *cr = createContext(s);
  // The rounded pixel size may exceed the sheet by a fraction of a pixel: no black (unset) border.
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  drawPage(cr, page, pxPerMetre);
  cairo_status_t st = cairo_status(cr);
  if (st == CAIRO_STATUS_SUCCESS) {
    st = cairo_surface_write_to_png(s, filename.c_str());
  }
  cairo_destroy(cr);
  cairo_surface_destroy(s);
  if (st != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(filename + ": cannot write: " + cairo_status_to_string(st));
  }
}

std::string fmt(const char *format, double a, double b = 0., double c = 0.)
{
  char buf[256];
  std::snprintf(buf, sizeof(buf), format, a, b, c);
  return buf;
}

Page makePage(const Options &opt)
{
  Page page;
  page.minRing = opt.minRingMm * kMm;
  Block header, legend;
  legend.scaleBar = true;
  std::string frame = "Target frame: X right, Y down, seen from this side; lengths in mm";
  if (opt.linear) {
    page.name = "ssl-linear";
    page.sheet = {-0.5 * kA4Width, -0.5 * kA4Height, 0.5 * kA4Width, 0.5 * kA4Height};
    page.linear = true;
    page.linearRect = {-0.5 * kLinearLength, -0.5 * kLinearHeight, 0.5 * kLinearLength, 0.5 * kLinearHeight};
    legend.lines.push_back(
        {fmt("Linear SSL (Briggs et al. 2000): %.1f mm x %.1f mm, p = 0.5", kLinearLength / kMm, kLinearHeight / kMm),
         kTextSize, false});
    legend.lines.push_back({"pattern origin (thinnest stripes) at the left edge", kTextSize, false});
    frame = "Origin at the pattern's centre. " + frame;
  } else {
    vpSSLTarget t = vpSSLTarget::fromName(opt.target);
    page.name = t.getName();
    double cx = t.getSheetCenterX(), cy = t.getSheetCenterY(), w = t.getSheetWidth(), h = t.getSheetHeight();
    page.sheet = {cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h};
    page.discs = t.getLandmarks();
    for (const vpSSLTargetLandmark &d : page.discs) {
      legend.lines.push_back({d.name +
                                  fmt(":  R = %.1f mm,  centre (%.1f, %.1f) mm", d.radius / kMm, d.x / kMm, d.y / kMm) +
                                  fmt(",  p = %g", d.p),
                              kTextSize, false});
    }
  }
  header.lines.push_back({page.name, kTitleSize, true});
  header.lines.push_back(
      {"Print at 100 % / actual size (no \"fit to page\") and check the 100 mm bar", kTextSize, false});
  header.lines.push_back({frame, kTextSize, false});
  header.lines.push_back({fmt("Rings thinner than %.2f mm are not drawn", opt.minRingMm), kTextSize, false});
  page.blocks.push_back(header);
  page.blocks.push_back(legend);
  return page;
}
} // namespace

int main(int argc, char **argv)
{
  // Cairo and fontconfig keep font caches until exit; releasing them keeps LeakSanitizer runs (CI)
  // clean. FcFini is looked up at run time because the tutorials link cairo, not fontconfig.
  struct CairoCleanup
  {
    ~CairoCleanup()
    {
      cairo_debug_reset_static_data();
      if (void *fcFini = dlsym(RTLD_DEFAULT, "FcFini")) {
        reinterpret_cast<void (*)()>(fcFini)();
      }
    }
  } cleanup;
  try {
    bool help = false;
    Options opt;
    Page page;
    try {
      opt = parseOptions(argc, argv, help);
      if (help) {
        printHelp(argv[0]);
        return 0;
      }
      page = makePage(opt);
      int pw = 0, ph = 0;
      pngSize(page, opt.dpi, pw, ph); // before anything is written
    } catch (const vpException &e) {
      std::cerr << "tutorial-ssl-target-generator: " << e.getStringMessage() << std::endl;
      return 2; // a bad target file: nothing written
    } catch (const std::runtime_error &e) {
      std::cerr << "tutorial-ssl-target-generator: " << e.what() << std::endl;
      return 2; // a bad option: nothing written
    }
    std::string prefix = opt.output.empty() ? page.name : opt.output;
    // The folder of the prefix is made if it does not exist yet (vpIoException if it cannot be).
    const std::string folder = vpIoTools::getParent(prefix);
    if (!folder.empty() && !vpIoTools::checkDirectory(folder)) {
      vpIoTools::makeDirectory(folder);
    }

    // Layout once, in sheet units, on a scratch surface; the three outputs then share it.
    cairo_surface_t *scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    cairo_t *cr = createContext(scratch);
    cairo_scale(cr, kPointsPerMetre, kPointsPerMetre);
    layout(cr, page);
    cairo_destroy(cr);
    cairo_surface_destroy(scratch);

    writeVector(page, prefix + ".pdf", true);
    writeVector(page, prefix + ".svg", false);
    int pw = 0, ph = 0;
    writePng(page, prefix + ".png", opt.dpi, pw, ph);

    std::cout << "Target " << page.name << ": sheet "
              << fmt("%.1f x %.1f mm", (page.sheet.x1 - page.sheet.x0) / kMm, (page.sheet.y1 - page.sheet.y0) / kMm)
              << std::endl;
    std::cout << "Wrote " << prefix << ".pdf, " << prefix << ".svg (1:1, print at actual size) and " << prefix
              << ".png (" << pw << " x " << ph << " px at " << opt.dpi << " dpi)" << std::endl;
    for (const vpSSLTargetLandmark &d : page.discs) {
      std::cout << "  " << d.name << ": R = " << d.radius / kMm << " mm, " << ringCount(d.radius, d.p, page.minRing)
                << " rings drawn" << std::endl;
    }
    if (page.linear) {
      std::cout << "  linear: " << ringCount(kLinearLength, page.linearP, page.minRing) << " stripes drawn"
                << std::endl;
    }
  } catch (const vpException &e) {
    std::cerr << "tutorial-ssl-target-generator: " << e.getStringMessage() << std::endl;
    return 1;
  } catch (const std::exception &e) {
    std::cerr << "tutorial-ssl-target-generator: " << e.what() << std::endl;
    return 1;
  } catch (...) {
    std::cerr << "tutorial-ssl-target-generator: unknown error" << std::endl;
    return 1;
  }
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "tutorial-ssl-target-generator: standard output: write error" << std::endl;
    return 1;
  }
  return 0;
}
