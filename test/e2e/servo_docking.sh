#!/usr/bin/env bash
# End-to-end check of what doc/servo-simulation.md claims of fig9 with SSL: the simulated AUV, guided by the SSL
# tracker on images rendered at 640x480, homes onto the 2 m stand-off, docks, and hits the board.
# About 20 s of CPU in Release (40 s of simulated time is enough: it docks at 27.8 s).
# Usage: bash servo_docking.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo "$@"

run_or_stop "fig9 with SSL" --scenario fig9 --method ssl --duration 40 --quiet --output-dir out

# The summary line: docked, and when.
python3 - run.log out/servo-fig9-ssl.csv <<'PY' 2>check.err && pass "fig9: docks as documented" || fail "fig9: $(cat check.err)"
import csv, re, sys
log = open(sys.argv[1]).read()
m = re.search(r"final state (\w+), stand-off RMS ([\d.]+) m over \d+ settled HOME steps, time to dock ([\d.]+) s", log)
assert m, "no summary line: " + log
state, rms, dock = m.group(1), float(m.group(2)), float(m.group(3))
rows = list(csv.DictReader(open(sys.argv[2])))
# The course: ALIGN, HOME, DOCK, DOCKED, in that order, never back to SEARCH (the target stays in view).
course = [r["state"] for i, r in enumerate(rows) if i == 0 or r["state"] != rows[i - 1]["state"]]
assert course == ["align", "home", "dock", "docked"], "course %s" % course
first = {s: float(next(r["t"] for r in rows if r["state"] == s)) for s in course}
# doc/servo-simulation.md, fig9 ssl over 40 s: HOME at 5.0 s, DOCK at 22.2 s, docked at 27.8 s, stand-off RMS 0.065 m.
assert state == "docked", "final state " + state
assert abs(first["home"] - 5.0) <= 1.0, "HOME at %.1f s, documented 5.0 s" % first["home"]
assert abs(first["dock"] - 22.2) <= 2.0, "DOCK at %.1f s, documented 22.2 s" % first["dock"]
assert abs(dock - 27.8) <= 2.0 and abs(first["docked"] - dock) < 0.01, "docked at %.1f s, documented 27.8 s" % dock
assert rms <= 0.08, "stand-off RMS %.3f m, documented 0.062 m" % rms
# Docked means the board was hit: the collision flag is up from the docking on, the camera at the board.
hit = [r for r in rows if r["collision"] == "1"]
assert hit and abs(float(hit[0]["t"]) - dock) < 0.01, "collision flag at %s, docked at %.1f s" % (hit[0]["t"] if hit else "never", dock)
assert float(hit[0]["true_range"]) < 0.15, "camera %.3f m from the target at the collision" % float(hit[0]["true_range"])
PY

e2e_finish
