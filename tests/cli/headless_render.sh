#!/bin/sh
# `bdfcar render` with no display: handed to bdfcar-headless (OSMesa), it
# writes frames of the requested size. Usage: headless_render.sh BDFCAR SCENARIO
set -e
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
env -u DISPLAY -u WAYLAND_DISPLAY "$1" render "$2" --out "$out" --size 320x180 --fps 5 --duration 1
n=$(ls "$out"/frame_*.png | wc -l)
[ "$n" -ge 5 ] || { echo "expected at least 5 frames, got $n"; exit 1; }
# PNG signature and the requested size in the IHDR chunk (width 320 = 0x140, height 180 = 0xb4).
head -c 24 "$out/frame_00000.png" | od -An -tx1 | tr -d ' \n' | grep -q '^89504e470d0a1a0a0000000d4948445200000140000000b4' \
  || { echo "frame is not a 320x180 PNG"; exit 1; }
# A video plays at the rate its frames were rendered at: 2 s of manoeuvre at
# 10 frames per second lasts 2 s (it played at 50 fps before).
if command -v ffprobe > /dev/null; then
  env -u DISPLAY -u WAYLAND_DISPLAY "$1" render "$2" --out "$out/v" --size 320x180 --fps 10 --duration 2 \
    --video "$out/run.mp4" > /dev/null
  d=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$out/run.mp4")
  awk -v d="$d" 'BEGIN { exit !(d > 1.85 && d < 2.25) }' || { echo "video lasts $d s, expected 2 s"; exit 1; }
  echo "ok: video $d s"
  # Video only (--no-frames): no PNG written, the same duration, from another camera.
  mkdir "$out/novideo"
  env -u DISPLAY -u WAYLAND_DISPLAY "$1" render "$2" --no-frames --camera top-down --size 320x180 --fps 10 \
    --duration 2 --video "$out/novideo/run.mp4" > /dev/null
  [ "$(ls "$out/novideo" | wc -l)" -eq 1 ] || { echo "--no-frames wrote more than the video: $(ls "$out/novideo")"; exit 1; }
  d=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "$out/novideo/run.mp4")
  awk -v d="$d" 'BEGIN { exit !(d > 1.85 && d < 2.25) }' || { echo "video-only lasts $d s, expected 2 s"; exit 1; }
  echo "ok: video only $d s"
fi
echo "ok: $n frames"
