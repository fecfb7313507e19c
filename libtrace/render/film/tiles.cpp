#include "render/film/tiles.h"

#include <string>

#include "core/error.h"

namespace rt {

namespace {

// Cut k of `parts` equal cuts of `size` pixels; 64-bit, since size x parts may pass 2^31.
int cut(int size, int parts, int k) { return int((long long)size * k / parts); }

}  // namespace

PixelWindow tileWindow(int width, int height, TileGrid grid, int index) {
    if (grid.columns < 1 || grid.rows < 1 || grid.columns > width || grid.rows > height)
        throw InputError("--tiles " + std::to_string(grid.columns) + "x" + std::to_string(grid.rows) +
                         " does not fit the " + std::to_string(width) + "x" + std::to_string(height) +
                         " image: every tile needs a pixel");
    if (index < 0 || index >= grid.count())
        throw InputError("--tile " + std::to_string(index) + " is outside 0-" + std::to_string(grid.count() - 1) +
                         " (the " + std::to_string(grid.columns) + "x" + std::to_string(grid.rows) + " tiles)");
    const int column = index % grid.columns, row = index / grid.columns;
    return {cut(width, grid.columns, column), cut(height, grid.rows, row), cut(width, grid.columns, column + 1),
            cut(height, grid.rows, row + 1)};
}

}  // namespace rt
