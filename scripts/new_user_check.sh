#!/usr/bin/env bash
# What a new user does first (issue 30), done by a script: `bdfcar drive` in
# a virtual X display (xvfb) with keys pressed through XTEST: drive off,
# the pause menu's "go to" the hill, the menu's car and fidelity (paper.toml
# on the linkage) and "drive them here", throttle, rewind ten times, quit.
# Checks what the drive printed and wrote: two drives, the second with the
# car and rung chosen at the hill, its rewinds as telemetry segments.
# Not a test (it paces keys on the wall clock, which a loaded machine
# stretches); a check to run by hand: bash scripts/new_user_check.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${BDFCAR_BIN:-$root/build/app/bdfcar}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/keys.py" <<'PY'
# keys.py ACTION ...: KEY (pressed and released), KEYxN (N times), holdKEY:S, sleepS.
import ctypes, sys, time
x = ctypes.CDLL("libX11.so.6"); t = ctypes.CDLL("libXtst.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
x.XStringToKeysym.restype = ctypes.c_ulong
x.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
t.XTestFakeKeyEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
x.XFlush.argtypes = [ctypes.c_void_p]
d = x.XOpenDisplay(None)
def key(name, down):
    t.XTestFakeKeyEvent(d, x.XKeysymToKeycode(d, x.XStringToKeysym(name.encode())), down, 0); x.XFlush(d)
for a in sys.argv[1:]:
    if a.startswith("sleep"): time.sleep(float(a[5:])); continue
    if a.startswith("hold"):
        name, s = a[4:].split(":"); key(name, 1); time.sleep(float(s)); key(name, 0); continue
    name, n = (a.rsplit("x", 1)[0], int(a.rsplit("x", 1)[1])) if a.rsplit("x", 1)[-1].isdigit() and "x" in a[1:] else (a, 1)
    for _ in range(n):
        key(name, 1); time.sleep(0.08); key(name, 0); time.sleep(0.25)
PY
cat > "$work/drive.sh" <<SH
export SDL_AUDIODRIVER=dummy
"$bin" drive --seconds 60 --telemetry "$work/run.csv" > "$work/out.txt" 2>&1 &
pid=\$!
# The drive has begun once its telemetry is being written.
for i in \$(seq 1 120); do [ -e "$work/run.csv.partial" ] && break; sleep 0.5; done
sleep 1
# The menu: 2 items, then the scene's places (the hill is the third), then car and fidelity.
places=\$(grep -c '^\[\[places\]\]' "$root/assets/scenarios/drive_powertrain.toml")
cars=\$(ls "$root"/assets/vehicles/*.toml | sort)
n=\$(echo "\$cars" | wc -l); now=\$(echo "\$cars" | grep -n '/sedan_drive.toml$' | cut -d: -f1); want=\$(echo "\$cars" | grep -n '/paper.toml$' | cut -d: -f1)
presses=\$(( (want - now + n) % n ))
python3 "$work/keys.py" holdUp:1.5 M Downx4 Return sleep1 M Downx\$((places + 2)) Returnx\$presses Down Return Down Return
for i in \$(seq 1 120); do [ -e "$work/run-2.csv.partial" ] && break; sleep 0.5; done
sleep 1
python3 "$work/keys.py" holdUp:3 BackSpacex10 sleep1 Escape
wait \$pid; echo "exit \$?" >> "$work/out.txt"
SH
timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" bash "$work/drive.sh" || true
cat "$work/out.txt"
python3 - "$work" <<'PY'
import csv, sys
w = sys.argv[1]
out = open(w + "/out.txt").read()
problems = []
if "exit 0" not in out: problems.append("the drive did not end with status 0")
if "driving paper" not in out or "on the linkage model" not in out: problems.append("no second drive with paper.toml on the linkage")
first = list(csv.DictReader(open(w + "/run.csv")))
second = list(csv.DictReader(open(w + "/run-2.csv")))
hill = (600.0, -60.0)
if int(first[-1]["segment"]) < 1: problems.append("the first drive never went to a place")
if abs(float(second[0]["x_m"]) - hill[0]) > 1 and abs(float(second[-1]["x_m"]) - hill[0]) > 60:
    problems.append("the second drive is not at the hill")
if int(second[-1]["segment"]) < 5: problems.append("the rewinds did not show as telemetry segments (%s)" % second[-1]["segment"])
print("second drive: %d rows, last segment %s, at x = %.1f m, y = %.1f m" % (len(second), second[-1]["segment"], float(second[-1]["x_m"]), float(second[-1]["y_m"])))
if problems:
    print("new-user check FAILED: " + "; ".join(problems)); sys.exit(1)
print("new-user check passed")
PY
