// rt-render -o sdl, the thesis's SDLRenderOutput (3.4.4, appendix B): a window that shows the
// picture as its blocks finish. The render threads only publish a finished block (they copy its
// linear pixels); the main thread converts what was published for the display, as the PNG
// output does, and updates the window at the display's rate. Esc or closing the window ends it.
// All SDL code is in sdl_window.cpp; a build without SDL2 (libsdl2-dev) has the class, whose
// constructor then says so.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "image/color_pipeline.h"
#include "render/film/framebuffer.h"
#include "render/renderer.h"

namespace rt::tool::render {

// A render the user stopped by closing the window: as an interrupted program (Ctrl-C) in a shell.
constexpr int kExitStoppedByUser = 130;

class SdlWindow {
public:
    // Whether this rt-render was built with SDL2.
    static bool compiledIn();

    // Opens a window the size of `window` (the pixels rendered). Throws rt::InputError when
    // SDL2 is not compiled in or no window can be opened (no display).
    SdlWindow(const PixelWindow& window, const ColorSettings& color, const std::string& title);
    ~SdlWindow();
    SdlWindow(const SdlWindow&) = delete;
    SdlWindow& operator=(const SdlWindow&) = delete;

    // Any thread: the pixels of `block` in `image` are final (RenderWatch::blockDone).
    void publish(const Framebuffer& image, const PixelWindow& block);

    // Main thread: shows the picture while running() is true; returns false if the user closed
    // the window (Esc, the close button) before that. Test hook: $RT_TEST_SDL_CLOSE_MS=N closes
    // it N milliseconds in.
    bool showWhile(const std::function<bool()>& running);
    // Main thread: shows the finished picture until the user closes the window. Test hook:
    // with $RT_TEST_SDL_DUMP set, writes what the window shows to that BMP file and returns.
    void showUntilClosed();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Runs work(watch) (the render, then writing its files) on a thread of its own while this, the
// main thread, shows its blocks in `window`. Closing the window stops the render and returns
// kExitStoppedByUser; once the render has finished the window stays until the user closes it,
// and 0 is returned. An exception from the work is thrown here.
int showWhileRendering(SdlWindow& window, const std::function<void(const RenderWatch&)>& work);

}  // namespace rt::tool::render
