# -o sdl (thesis appendix B): the window, read back, shows the rendered picture; -f is written as
# soon as the render finishes, while the window stays; closing it during a render stops it (exit
# 130, nothing written); with no display it fails at once (exit 2). Needs Xvfb (Debian xvfb), else skips.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
# Under ASan (the asan preset), SDL's video driver leaks from libraries it loads and unloads
# again (240 bytes, stacks ending in an "<unknown module>" that no suppression can name): leak
# checking is off for this test alone; ASan's and UBSan's other checks stay on.
if built_with "$RT_RENDER" asan; then export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"; fi

"$RT_RENDER" --version >"$WORK/version.txt"
if ! grep -q "^outputs:.* sdl" "$WORK/version.txt"; then
    grep -q "^outputs: null png" "$WORK/version.txt" || fail "--version lists no outputs: $(cat "$WORK/version.txt")"
    expect_exit 2 "$RT_RENDER" "$scene" -o sdl
    expect_one_error rt-render "built without SDL2"
    echo "SKIP: rt-render was built without SDL2 (libsdl2-dev)" >&2
    exit 77
fi

expect_exit 2 env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$RT_RENDER" "$scene" -o sdl -x 64 -y 48
expect_one_error rt-render "no display"
expect_exit 2 "$RT_RENDER" "$scene" -o sdl --orbit 4 -f "$WORK/o_#.png"
expect_one_error rt-render "not with --orbit"

command -v Xvfb >/dev/null || { echo "SKIP: no Xvfb (Debian xvfb) to open a window in" >&2; exit 77; }
# One virtual display for the test, on a free number that Xvfb picks and writes to fd 3.
Xvfb -displayfd 3 -nolisten tcp -screen 0 1024x768x24 3>"$WORK/display" 2>/dev/null &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$WORK"' EXIT
for _ in $(seq 100); do [ -s "$WORK/display" ] && break; sleep 0.1; done
[ -s "$WORK/display" ] || fail "Xvfb did not start"
export DISPLAY=":$(cat "$WORK/display")"
in_xvfb() { timeout 120 "$@"; }

# The window's pixels, read back (test hook RT_TEST_SDL_DUMP), are the 8-bit picture -f writes.
opts=(-K -s -d 3 -x 96 -y 64 -S 2 -q --alpha off)
in_xvfb env RT_TEST_SDL_DUMP="$WORK/window.bmp" "$RT_RENDER" "$scene" "${opts[@]}" -o sdl -f "$WORK/file.png" ||
    fail "-o sdl under Xvfb failed"
idiff -fail 0 -warn 0 "$WORK/file.png" "$WORK/window.bmp" >"$WORK/idiff.txt" ||
    fail "the window does not show the picture: $(cat "$WORK/idiff.txt")"
# ... and the comparison can fail: a region shows less.
in_xvfb env RT_TEST_SDL_DUMP="$WORK/region.bmp" "$RT_RENDER" "$scene" "${opts[@]}" -o sdl --region 0,0,96,32
if idiff -fail 0 -warn 0 "$WORK/file.png" "$WORK/region.bmp" >/dev/null 2>&1; then fail "idiff passed a region"; fi

# -f is written when the render finishes, while the window waits for Esc.
"$RT_RENDER" "$scene" "${opts[@]}" -o sdl -f "$WORK/early.png" &
pid=$!
for _ in $(seq 600); do [ -s "$WORK/early.png" ] && break; sleep 0.1; done
[ -s "$WORK/early.png" ] || fail "-f was not written while the window was open"
sleep 0.5
kill -0 $pid 2>/dev/null || fail "the window closed by itself after the render"
kill $pid
wait $pid || true

# Closing the window during a long render stops it at once: exit 130, no file.
expect_exit 130 in_xvfb env RT_TEST_SDL_CLOSE_MS=500 "$RT_RENDER" "$scene" -K -s -d 5 -x 800 -y 600 -S 64 -o sdl \
    -f "$WORK/stopped.png"
[ ! -e "$WORK/stopped.png" ] || fail "a stopped render wrote its file"
echo "render_sdl: ok"
