#include "embree_scene.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "core/stopwatch.h"

namespace rt::bench {

namespace {

constexpr unsigned kTriangleGeometry = 0;
constexpr unsigned kSphereGeometry = 1;

// Embree reports every allocation (bytes > 0) and release (bytes < 0); returning true lets it proceed.
bool countBytes(void* counter, ssize_t bytes, bool /*post*/) {
    static_cast<std::atomic<std::int64_t>*>(counter)->fetch_add(bytes, std::memory_order_relaxed);
    return true;
}

void throwOnError(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree failed in ") + what);
}

// ---- Triangles: one mesh with three vertices of its own per triangle, as rt stores them.

void attachTriangles(RTCDevice device, RTCScene scene, const Primitives& prims) {
    const RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t n = prims.count<Triangle>();
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    for (std::size_t i = 0; i < n; ++i) {
        const Triangle& t = prims.all<Triangle>()[std::uint32_t(i)];
        for (int c = 0; c < 3; ++c) {
            const Vec3& p = c == 0 ? t.p0 : c == 1 ? t.p1 : t.p2;
            for (int a = 0; a < 3; ++a) vertices[9 * i + 3 * c + a] = float(p[a]);
            indices[3 * i + c] = unsigned(3 * i + c);
        }
    }
    rtcCommitGeometry(mesh);
    rtcAttachGeometryByID(scene, mesh, kTriangleGeometry);
    rtcReleaseGeometry(mesh);
}

// ---- Spheres: user geometry calling rt's intersectSphere for each ray of a packet.

void sphereBounds(const RTCBoundsFunctionArguments* args) {
    const auto* prims = static_cast<const Primitives*>(args->geometryUserPtr);
    const Aabb b = prims->bounds(prims->count<Triangle>() + args->primID);
    *args->bounds_o = {float(b.lo.x), float(b.lo.y), float(b.lo.z), 0, float(b.hi.x), float(b.hi.y), float(b.hi.z), 0};
}

// The direction is normalised again in Real: rounded to float it is unit only to about
// 1e-7, and the sphere test's l^2 - tca^2 magnifies that into errors of 1e-4 in t on
// the balls scene's small spheres.
Ray rayOf(RTCRayN* ray, unsigned n, unsigned i) {
    return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
            normalize(Vec3{RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)})};
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto* prims = static_cast<const Primitives*>(args->geometryUserPtr);
    const Sphere& sphere = prims->all<Sphere>()[args->primID];
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        Real t;
        if (args->valid[i] != -1 || !intersectSphere(sphere, rayOf(ray, args->N, i), RTCRayN_tfar(ray, args->N, i), t))
            continue;
        RTCRayN_tfar(ray, args->N, i) = float(t);
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
        RTCHitN_u(hit, args->N, i) = RTCHitN_v(hit, args->N, i) = 0;
    }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto* prims = static_cast<const Primitives*>(args->geometryUserPtr);
    const Sphere& sphere = prims->all<Sphere>()[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        Real t;
        if (args->valid[i] == -1 &&
            intersectSphere(sphere, rayOf(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i), t))
            RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();  // Embree's "occluded"
    }
}

void attachSpheres(RTCDevice device, RTCScene scene, const Primitives& prims) {
    const RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, prims.count<Sphere>());
    rtcSetGeometryUserData(geometry, const_cast<Primitives*>(&prims));
    rtcSetGeometryBoundsFunction(geometry, sphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, sphereIntersect);
    rtcSetGeometryOccludedFunction(geometry, sphereOccluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, kSphereGeometry);
    rtcReleaseGeometry(geometry);
}

void setRay(RTCRay& r, const Ray& ray, Real tMax) {
    r.org_x = float(ray.origin.x), r.org_y = float(ray.origin.y), r.org_z = float(ray.origin.z);
    r.dir_x = float(ray.direction.x), r.dir_y = float(ray.direction.y), r.dir_z = float(ray.direction.z);
    r.tnear = 0;
    r.tfar = float(tMax);
    r.time = 0;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
}

}  // namespace

EmbreeScene::EmbreeScene(const Primitives& prims, int threads) : prims_(prims) {
    device_ = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
    if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
    rtcSetDeviceMemoryMonitorFunction(device_, countBytes, &bytes_);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (prims.count<Triangle>() > 0) attachTriangles(device_, scene_, prims);
    if (prims.count<Sphere>() > 0) attachSpheres(device_, scene_, prims);
    const Stopwatch stopwatch;
    rtcCommitScene(scene_);
    buildSeconds_ = stopwatch.seconds();
    throwOnError(device_, "building the scene");
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

std::int64_t EmbreeScene::memoryBytes() const {
    return bytes_.load() + std::int64_t(prims_.count<Sphere>() * sizeof(Sphere));
}

bool EmbreeScene::intersect(const Ray& ray, Real tMax, Hit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    setRay(rh.ray, ray, tMax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    hit.prim = rh.hit.geomID == kSphereGeometry ? prims_.count<Triangle>() + rh.hit.primID : rh.hit.primID;
    hit.u = rh.hit.u, hit.v = rh.hit.v;
    return true;
}

bool EmbreeScene::occluded(const Ray& ray, Real tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    setRay(r, ray, tMax);
    rtcOccluded1(scene_, &context, &r);
    return r.tfar < 0;
}

void EmbreeScene::occluded8(const Ray* rays, const Real* tMax, int count, bool* blocked) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(32) int valid[kPacketSize];
    alignas(32) RTCRay8 r;
    for (int i = 0; i < kPacketSize; ++i) {
        valid[i] = i < count ? -1 : 0;
        const int k = i < count ? i : 0;  // lanes past `count` repeat ray 0 and stay off
        r.org_x[i] = float(rays[k].origin.x), r.org_y[i] = float(rays[k].origin.y);
        r.org_z[i] = float(rays[k].origin.z);
        r.dir_x[i] = float(rays[k].direction.x), r.dir_y[i] = float(rays[k].direction.y);
        r.dir_z[i] = float(rays[k].direction.z);
        r.tnear[i] = 0, r.tfar[i] = float(tMax[k]);
        r.time[i] = 0, r.mask[i] = ~0u, r.id[i] = 0, r.flags[i] = 0;
    }
    rtcOccluded8(valid, scene_, &context, &r);
    for (int i = 0; i < count; ++i) blocked[i] = r.tfar[i] < 0;
}

void EmbreeScene::intersect8(const Ray* rays, Hit* hits, bool* found) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(32) int valid[kPacketSize];
    alignas(32) RTCRayHit8 rh;
    for (int i = 0; i < kPacketSize; ++i) {
        valid[i] = -1;
        rh.ray.org_x[i] = float(rays[i].origin.x), rh.ray.org_y[i] = float(rays[i].origin.y);
        rh.ray.org_z[i] = float(rays[i].origin.z);
        rh.ray.dir_x[i] = float(rays[i].direction.x), rh.ray.dir_y[i] = float(rays[i].direction.y);
        rh.ray.dir_z[i] = float(rays[i].direction.z);
        rh.ray.tnear[i] = 0, rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
        rh.ray.time[i] = 0, rh.ray.mask[i] = ~0u, rh.ray.id[i] = 0, rh.ray.flags[i] = 0;
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, scene_, &context, &rh);
    for (int i = 0; i < kPacketSize; ++i) {
        found[i] = rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        if (!found[i]) continue;
        hits[i].t = rh.ray.tfar[i];
        hits[i].prim =
            rh.hit.geomID[i] == kSphereGeometry ? prims_.count<Triangle>() + rh.hit.primID[i] : rh.hit.primID[i];
        hits[i].u = rh.hit.u[i], hits[i].v = rh.hit.v[i];
    }
}

}  // namespace rt::bench
