// The RAW model format of thesis appendix D, little-endian:
//   offset 0  "raw3d"                 magic, 5 bytes
//   offset 5  'T' or 'S'              triangles or spheres
//   offset 6  uint32 count            number of primitives
//   offset 10 count * 9 float32       triangles: three vertices x, y, z
//          or count * 4 float32       spheres: centre x, y, z and radius
// A file holds one kind of primitive. rt extension: after triangles, optional sections of
// per-corner data, each a 4-byte tag and count * N float32 (docs/scene-format.md):
//   "vnrm" N = 9  vertex normals      "vtex" N = 6  texture coordinates      "vcol" N = 9  colours
// A thesis file (nothing after the data) reads as before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>

#include "scene/scene.h"

namespace rt {

constexpr std::size_t kRawHeaderBytes = 10;

// Reads a RAW file into a Model's geometry (name, file and format are left for the caller).
// Throws rt::InputError "path: byte N: what" for a short file, a wrong magic, an unknown
// type, a count that does not match the size exactly (for triangles: with the sections
// after them), an unknown or repeated section, or a NaN or infinite number. Sizes are
// checked against the file size before anything is allocated.
Model readRawFile(const std::string& path);

// The same from bytes in memory (inline model data); `name` is used in messages.
Model readRawBytes(std::span<const std::uint8_t> bytes, const std::string& name);

// Writes a model's geometry as RAW, with a section for each per-corner array it has. A file
// holds one kind of primitive, so a model with both triangles and spheres, or with per-corner
// arrays that do not cover its triangles, throws std::invalid_argument; an empty model is "T", 0.
void writeRaw(std::ostream& out, const Model& model);
// writeRaw to a file, atomically (os/atomic_file.h).
void writeRawFile(const std::string& path, const Model& model);

}  // namespace rt
