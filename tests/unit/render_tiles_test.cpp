// The tiles of --tiles CxR --tile I/N meet exactly and cover the image, for any size.
#include <gtest/gtest.h>

#include <vector>

#include "core/error.h"
#include "render/film/tiles.h"

using namespace rt;

namespace {

// How many tiles of the grid hold each pixel: 1 everywhere means no gap and no overlap.
std::vector<int> coverCount(int width, int height, TileGrid grid) {
    std::vector<int> count(std::size_t(width) * height, 0);
    for (int i = 0; i < grid.count(); ++i) {
        const PixelWindow w = tileWindow(width, height, grid, i);
        EXPECT_TRUE(w.inside(width, height)) << "tile " << i;
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) ++count[std::size_t(y) * width + x];
    }
    return count;
}

}  // namespace

TEST(RenderTiles, EveryPixelIsInExactlyOneTile) {
    for (const int width : {1, 4, 7, 70, 97, 1920})
        for (const int height : {1, 3, 40, 1080})
            for (const TileGrid grid :
                 {TileGrid{1, 1}, TileGrid{4, 4}, TileGrid{3, 1}, TileGrid{1, 3}, TileGrid{7, 2}}) {
                if (grid.columns > width || grid.rows > height) continue;
                const std::vector<int> count = coverCount(width, height, grid);
                for (std::size_t p = 0; p < count.size(); ++p)
                    ASSERT_EQ(count[p], 1) << width << "x" << height << " in " << grid.columns << "x" << grid.rows
                                           << " tiles, pixel " << p % width << "," << p / width;
            }
}

TEST(RenderTiles, TilesGoRowByRowFromTheTopLeft) {
    const TileGrid grid{4, 4};
    EXPECT_EQ(tileWindow(70, 40, grid, 0), (PixelWindow{0, 0, 17, 10}));
    EXPECT_EQ(tileWindow(70, 40, grid, 1), (PixelWindow{17, 0, 35, 10}));
    EXPECT_EQ(tileWindow(70, 40, grid, 4), (PixelWindow{0, 10, 17, 20}));
    EXPECT_EQ(tileWindow(70, 40, grid, 15), (PixelWindow{52, 30, 70, 40}));
}

TEST(RenderTiles, SizesDifferByAtMostOnePixel) {
    const TileGrid grid{7, 3};
    for (int i = 0; i < grid.count(); ++i) {
        const PixelWindow w = tileWindow(100, 20, grid, i);
        EXPECT_TRUE(w.width() == 14 || w.width() == 15) << "tile " << i << " is " << w.width() << " wide";
        EXPECT_TRUE(w.height() == 6 || w.height() == 7) << "tile " << i << " is " << w.height() << " high";
    }
}

TEST(RenderTiles, LargestImageDoesNotOverflow) {
    const TileGrid grid{65536, 1};
    EXPECT_EQ(tileWindow(65536, 1, grid, 65535), (PixelWindow{65535, 0, 65536, 1}));
}

TEST(RenderTiles, BadIndexOrGridIsInputError) {
    EXPECT_THROW(tileWindow(70, 40, TileGrid{4, 4}, 16), InputError);
    EXPECT_THROW(tileWindow(70, 40, TileGrid{4, 4}, -1), InputError);
    EXPECT_THROW(tileWindow(3, 40, TileGrid{4, 4}, 0), InputError);  // more columns than pixels
    EXPECT_THROW(tileWindow(70, 40, TileGrid{0, 4}, 0), InputError);
}
