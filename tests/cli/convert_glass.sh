# rt-convert writes glass (docs/conversion.md, "Glass"): TransmissionRoughnessTest's five
# KHR_materials_transmission rows keep their KHR_materials_ior and, having a KHR_materials_volume,
# refract as solids; its opaque row stays opaque. CornellBox-Sphere's illum 7 sphere is glass of
# its Ni, its illum 5 sphere a mirror. Both written scenes render.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models"

expect_exit 0 "$RT_CONVERT" -q "$MODELS/glb/TransmissionRoughnessTest/TransmissionRoughnessTest.glb" -o "$WORK/trt.xml"
for ior in 1 1.33 1.5 1.76 2.42; do
    line=$(grep "name=\"Mat_IOR_" "$WORK/trt.xml" | grep " ior=\"$ior\"") || fail "no glass of ior $ior in trt.xml"
    case $line in *'transmission="1"'*) ;; *) fail "ior $ior: not fully transmissive: $line" ;; esac
    case $line in *'thin='*) fail "ior $ior: thin, though the material has a volume: $line" ;; esac
done
grep 'name="Mat_Opaque"' "$WORK/trt.xml" | grep -q transmission && fail "Mat_Opaque lets light through"
expect_exit 0 "$RT_RENDER" "$WORK/trt.xml" -x 64 -y 48 -s -q -f "$WORK/trt.png"

expect_exit 0 "$RT_CONVERT" -q "$MODELS/obj/CornellBox-Sphere/CornellBox-Sphere.obj" -o "$WORK/cbs.xml"
grep 'name="rightSphere"' "$WORK/cbs.xml" | grep 'transmission="1"' | grep -q 'ior="2.5"' ||
    fail "rightSphere (illum 7, Ni 2.5) is not glass: $(grep rightSphere "$WORK/cbs.xml")"
grep 'name="leftSphere"' "$WORK/cbs.xml" | grep -q 'reflection="0.95"' ||
    fail "leftSphere (illum 5, Ks 0.95) is no mirror: $(grep leftSphere "$WORK/cbs.xml")"
expect_exit 0 "$RT_RENDER" "$WORK/cbs.xml" -x 64 -y 48 -s -q -f "$WORK/cbs.png"
echo "convert_glass: ok"
