# --packets on (camera rays eight at a time) gives the bits of --packets off on real models:
# textures with ray differentials (jeep1), cut-outs and single-sided surfaces under a hit
# filter (AlphaBlendModeTest), on SSE2, AVX2 and AVX-512 lanes (RT_SIMD; a level the CPU lacks
# runs the default) and on one or two threads.
source "$(dirname "$0")/common.bash"
need_shared_models
models=("$RT_SHARED_DIR/models/3ds/jeep1/jeep1.3ds" "$RT_SHARED_DIR/models/glb/AlphaBlendModeTest/AlphaBlendModeTest.glb")
opts=(-q -x 90 -y 70 -s --progress none)
for model in "${models[@]}"; do
    name=$(basename "$model")
    RT_SIMD=sse2 "$RT_RENDER" "$model" "${opts[@]}" --packets off --threads 1 -f "$WORK/off.png" --stats-json "$WORK/off.json"
    for simd in sse2 avx2 avx512; do
        for threads in 1 2; do
            RT_SIMD=$simd "$RT_RENDER" "$model" "${opts[@]}" --packets on --threads $threads -f "$WORK/on.png" \
                --stats-json "$WORK/on.json"
            cmp -s "$WORK/on.png" "$WORK/off.png" || fail "$name, $simd, $threads threads: packets change the picture"
            for counter in rays traversalSteps intersectionTests; do
                [ "$(grep -o "\"$counter\": [0-9]*" "$WORK/on.json")" = "$(grep -o "\"$counter\": [0-9]*" "$WORK/off.json")" ] ||
                    fail "$name, $simd: packets change the $counter"
            done
        done
    done
done
expect_exit 2 "$RT_RENDER" "${models[0]}" -q -o null --packets maybe
echo "render_packets: ok"
