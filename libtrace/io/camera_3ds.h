// The cameras of a 3DS file, read from the file's own camera chunks.
//
// Assimp 5.2.5's 3DS reader cannot be corrected after the fact: it puts the camera's position
// both in the aiCamera and in the camera node's transform, replaces the look direction of
// animated camera nodes by (0,0,1), and stores the lens (millimetres) as an angle. So rt reads
// the camera chunks itself and lets Assimp read everything else.
//
// Chunk layout (3D Studio; lib3ds, Assimp's 3DSLoader.cpp): every chunk starts with a uint16
// id and a uint32 length that includes its 6-byte header, little-endian. The cameras sit in
//   0x4D4D main > 0x3D3D editor > 0x4000 named object (zero-terminated name, then chunks)
//     > 0x4700 camera: position xyz, target xyz, bank angle (degrees), lens (mm), float32 each.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/aabb.h"
#include "core/transform.h"
#include "scene/scene.h"

namespace rt {

// One 0x4700 chunk, in the file's (Z-up) coordinates.
struct Camera3ds {
    std::string name;  // the named object that holds it
    Vec3 position;
    Vec3 target;
    double bankDegrees = 0;  // roll about the view direction
    double lensMm = 0;
};

// The camera chunks of a 3DS file in file order. Never reads past a chunk's or the file's
// end: a chunk that runs past its parent, a name without its terminating zero, a short
// camera chunk or a NaN/infinite camera number is an rt::InputError "name: byte N: what".
std::vector<Camera3ds> read3dsCameras(std::span<const std::uint8_t> bytes, const std::string& name);
std::vector<Camera3ds> read3dsCamerasFromFile(const std::string& path);

// 3D Studio's lens-to-angle rule, fov = 2400 / lens degrees (lib3ds does the same): a 3DS file
// written by 3ds Max stores lens = 2400 / fov, so this gives back the horizontal fov the
// artist set (TargetCameraAnim.3ds: lens 53.333 mm, its FOV key 45 degrees).
double fovDegreesFromLens(double lensMm);

// rt's camera for a 3DS camera whose file coordinates `fileToWorld` takes to the scene: it
// looks from position to target, its up is the file's +Z (-X when it looks straight along Z)
// rolled counter-clockwise, as seen from behind the camera, by the bank angle.
Camera cameraFrom3ds(const Camera3ds& camera, const Transform& fileToWorld);

}  // namespace rt
