# docs/render-farm.md stays true: its `rt-farm submit --dry-run` block is what rt-farm prints
# (paths aside), and its commands without rt-farm, run as written at a small size, give merged
# float tiles equal to a direct render, and a PNG made from them equal to a PNG rendered
# directly, bit for bit.
source "$(dirname "$0")/common.bash"
doc="$RT_SOURCE_DIR/docs/render-farm.md"
farm="$RT_SOURCE_DIR/tools/farm/rt-farm"

# The code block that contains the line matching $1, without its fences.
block() { awk -v line="$1" '/^```/ { if (inside && found) exit; inside = !inside; body = ""; next }
                             inside { body = body $0 "\n"; if ($0 ~ line) found = 1 }
                             END { printf "%s", found ? body : "" }' "$doc"; }

mkdir "$WORK/project"
cp "$RT_SOURCE_DIR/scenes/demo.xml" "$WORK/project/scene.xml"
(cd "$WORK/project" && "$farm" submit scene.xml -K -s -d 5 -S 16 -D b -x 1920 -y 1080 --tiles 4x4 -o farm \
    --partition main --time 1:00:00 --cpus-per-task 8 --dry-run) |
    sed -e "s|$(readlink -f "$RT_RENDER")|/usr/local/bin/rt-render|" -e "s|$(readlink -f "$farm")|/usr/local/bin/rt-farm|" \
        -e "s|$WORK/project|/home/me/project|g" >"$WORK/dry-run.txt"
block '^# /home/me/project/farm/task.sbatch' >"$WORK/doc-dry-run.txt"
[ -s "$WORK/doc-dry-run.txt" ] || fail "the doc's --dry-run block was not found"
diff "$WORK/doc-dry-run.txt" "$WORK/dry-run.txt" >"$WORK/diff.txt" ||
    fail "docs/render-farm.md's --dry-run output is not what rt-farm prints: $(cat "$WORK/diff.txt")"

mkdir "$WORK/bin" "$WORK/farm"
ln -s "$RT_RENDER" "$WORK/bin/rt-render"
export PATH="$WORK/bin:$PATH"
block '^mkdir -p tiles' | sed 's/-x 640 -y 480 /-x 64 -y 48 /' >"$WORK/tiles.sh"
grep -q -- '-x 64 -y 48 ' "$WORK/tiles.sh" || fail "the doc's tile commands changed: $(cat "$WORK/tiles.sh")"
block '^oiiotool --colorconfig' | sed "s|config/ocio/config.ocio|$RT_SOURCE_DIR/config/ocio/config.ocio|" >"$WORK/png.sh"
[ -s "$WORK/png.sh" ] || fail "the doc's PNG command was not found"
cd "$WORK/farm"
cp "$RT_SOURCE_DIR/scenes/demo.xml" scene.xml
bash "$WORK/tiles.sh" 2>"$WORK/tiles.log" || fail "the doc's tiles failed: $(cat "$WORK/tiles.log")"
bash "$WORK/png.sh"

direct=(-K -s -d 5 -S 16 -x 64 -y 48)  # the doc's options at the same size
"$RT_RENDER" scene.xml "${direct[@]}" -q --exr-pixels float -f direct.exr
"$RT_RENDER" scene.xml "${direct[@]}" -q -f direct.png
idiff -fail 0 -warn 0 direct.exr full.exr >"$WORK/idiff.txt" || fail "merged tiles differ: $(cat "$WORK/idiff.txt")"
idiff -fail 0 -warn 0 direct.png full.png >"$WORK/idiff.txt" || fail "the PNG of the tiles differs: $(cat "$WORK/idiff.txt")"
echo "render_farm_doc: ok"
