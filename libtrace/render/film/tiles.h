// The tiles of a render farm (rt-render --tiles CxR --tile I/N): the image cut into a grid of
// C columns and R rows, task I rendering tile I, row by row from the top left. The cuts sit at
// k x width / C (rounded down), so neighbouring tiles meet exactly and together cover any image
// size; tile sizes differ by at most one pixel.
#pragma once

#include "render/film/framebuffer.h"

namespace rt {

struct TileGrid {
    int columns = 1, rows = 1;
    int count() const { return columns * rows; }
};

// Tile `index` (0 to grid.count() - 1) of a width x height image. Throws rt::InputError if the
// index is outside the grid or the grid has more columns or rows than the image has pixels.
PixelWindow tileWindow(int width, int height, TileGrid grid, int index);

}  // namespace rt
