#!/usr/bin/env bash
# End-to-end check of the re-acquisition of doc/servo-simulation.md's fig7 with SSL: the target is taken out of
# the water while the vehicle holds the stand-off, the vehicle searches, and when the target is put back the SSL
# tracker re-acquires it and the vehicle homes again. fig7's events scale with its duration D (out at 0.47 D, back
# at 0.75 D): D = 90 s keeps the run to about 45 s of CPU in Release, the whole course included.
# Usage: bash servo_reacquisition.sh TUTORIAL_BIN_DIR DATA_DIR   (run from a scratch directory)
source "$(dirname "${BASH_SOURCE[0]}")/common.bash" tutorial-ssl-servo "$@"

run_or_stop "fig7 (D = 90 s) with SSL" --scenario fig7 --method ssl --duration 90 --quiet --output-dir out

python3 - run.log out/servo-fig7-ssl.csv <<'PY' 2>check.err && pass "fig7: searches, re-acquires, homes again" || fail "fig7: $(cat check.err)"
import csv, re, sys
log = open(sys.argv[1]).read()
assert re.search(r"final state home,", log), "final state: " + log
rows = list(csv.DictReader(open(sys.argv[2])))
course = [(float(r["t"]), r["state"]) for i, r in enumerate(rows) if i == 0 or r["state"] != rows[i - 1]["state"]]
states = [s for _, s in course]
# doc/servo-simulation.md, fig7 ssl: ALIGN, HOME; SEARCH 3.2 s after the target is taken out; re-acquired (ALIGN)
# 11.2 s after it is put back, then HOME. Here D = 90 s: out at 42.3 s, back at 67.5 s.
out_t, back_t = 0.47 * 90, 0.75 * 90
assert states == ["align", "home", "search", "align", "home"], "course %s" % course
t_search, t_align, t_home = course[2][0], course[3][0], course[4][0]
assert out_t < t_search <= out_t + 4.0, "SEARCH at %.1f s, the target out at %.1f s" % (t_search, out_t)
assert back_t < t_align <= back_t + 12.0, "re-acquired at %.1f s, the target back at %.1f s" % (t_align, back_t)
assert t_align < t_home <= t_align + 6.5, "HOME at %.1f s after ALIGN at %.1f s" % (t_home, t_align)
# Nothing is seen while the target is out of the water: no false re-acquisition.
seen_out = [r["t"] for r in rows if out_t + 0.5 < float(r["t"]) < back_t and r["nb_points"] != "0"]
assert not seen_out, "target points measured while it is out of the water at t = %s" % seen_out[:3]
# Homing again: the range comes back to the 2 m stand-off.
end = [float(r["true_range"]) for r in rows if float(r["t"]) >= 85.0 and r["true_range"]]
assert end and max(abs(x - 2.0) for x in end) < 0.2, "range at the end %s" % end[:5]
PY

e2e_finish
