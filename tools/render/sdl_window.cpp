#include "sdl_window.h"

#include <atomic>
#include <exception>
#include <thread>

#include "core/error.h"

#ifdef RT_HAVE_SDL2

#include <SDL.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace rt::tool::render {

namespace {

constexpr Uint32 kFrameMs = 16;  // about 60 updates a second: the display's rate, not the render's

// A display value as the 8-bit PNG output stores it (OpenImageIO's float to uint8: scale, round, clamp),
// so that the window shows the same bytes as -f out.png --alpha off.
std::uint8_t toByte(float v) {
    const float s = v * 255.0f;
    return std::uint8_t(std::clamp(s + (s < 0 ? -0.5f : 0.5f), 0.0f, 255.0f));
}

std::string sdlError(const std::string& what) { return "-o sdl: " + what + ": " + SDL_GetError(); }

// The user ended the window: Esc, or the window's close button.
bool closes(const SDL_Event& e) {
    return e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE) ||
           (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE);
}

}  // namespace

struct SdlWindow::Impl {
    PixelWindow window;
    ColorPipeline color;
    SDL_Window* sdlWindow = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    // What the render threads publish: the window's linear colours and the blocks not yet shown.
    std::mutex mutex;
    std::vector<Color> published;
    std::vector<PixelWindow> pending;

    Impl(const PixelWindow& w, const ColorSettings& settings)
        : window(w), color(settings), published(std::size_t(w.width()) * std::size_t(w.height())) {}

    // The pending blocks' pixels, taken under the lock and converted for the display outside it.
    void showPending() {
        std::vector<PixelWindow> blocks;
        std::vector<std::vector<float>> rgb;
        {
            const std::lock_guard<std::mutex> lock(mutex);
            blocks.swap(pending);
            for (const PixelWindow& b : blocks) rgb.push_back(linearPixels(b));
        }
        for (std::size_t i = 0; i < blocks.size(); ++i) upload(blocks[i], rgb[i]);
        SDL_RenderClear(renderer);
        SDL_RenderCopy(renderer, texture, nullptr, nullptr);
        SDL_RenderPresent(renderer);
    }

    std::vector<float> linearPixels(const PixelWindow& b) const {
        std::vector<float> rgb;
        rgb.reserve(std::size_t(b.width()) * std::size_t(b.height()) * 3);
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x) {
                const Color& c =
                    published[std::size_t(y - window.y0) * std::size_t(window.width()) + std::size_t(x - window.x0)];
                rgb.insert(rgb.end(), {c.r, c.g, c.b});
            }
        return rgb;
    }

    void upload(const PixelWindow& b, std::vector<float>& rgb) {
        color.toDisplay(rgb);
        std::vector<std::uint8_t> bytes(rgb.size());
        std::transform(rgb.begin(), rgb.end(), bytes.begin(), toByte);
        const SDL_Rect rect{b.x0 - window.x0, b.y0 - window.y0, b.width(), b.height()};
        SDL_UpdateTexture(texture, &rect, bytes.data(), b.width() * 3);
    }

    // Test hook ($RT_TEST_SDL_DUMP): the window's pixels, read back, to a BMP file.
    void dump(const char* path) {
        SDL_Surface* surface =
            SDL_CreateRGBSurfaceWithFormat(0, window.width(), window.height(), 24, SDL_PIXELFORMAT_RGB24);
        if (!surface) throw std::runtime_error(sdlError("cannot read the window back"));
        const bool ok =
            SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGB24, surface->pixels, surface->pitch) == 0 &&
            SDL_SaveBMP(surface, path) == 0;
        SDL_FreeSurface(surface);
        if (!ok) throw std::runtime_error(sdlError(std::string("cannot write ") + path));
    }

    ~Impl() {
        if (texture) SDL_DestroyTexture(texture);
        if (renderer) SDL_DestroyRenderer(renderer);
        if (sdlWindow) SDL_DestroyWindow(sdlWindow);
        SDL_Quit();
    }
};

bool SdlWindow::compiledIn() { return true; }

SdlWindow::SdlWindow(const PixelWindow& window, const ColorSettings& color, const std::string& title) {
    // Without a display SDL would fall back to its offscreen driver: an invisible window waiting for an Esc
    // that never comes. SDL_VIDEODRIVER, if set, says the user wants whatever driver it names.
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") && !std::getenv("SDL_VIDEODRIVER"))
        throw InputError("-o sdl: no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set)");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) throw InputError(sdlError("cannot open a window"));
    impl_ = std::make_unique<Impl>(window, color);
    Impl& w = *impl_;
    w.sdlWindow = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, window.width(),
                                   window.height(), 0);
    // The software renderer: what it shows is exactly the bytes uploaded, on any display.
    if (w.sdlWindow) w.renderer = SDL_CreateRenderer(w.sdlWindow, -1, SDL_RENDERER_SOFTWARE);
    if (w.renderer)
        w.texture = SDL_CreateTexture(w.renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STATIC, window.width(),
                                      window.height());
    if (!w.texture) throw InputError(sdlError("cannot open a window"));
    SDL_SetRenderDrawColor(w.renderer, 0, 0, 0, 255);
    w.showPending();
}

SdlWindow::~SdlWindow() = default;

void SdlWindow::publish(const Framebuffer& image, const PixelWindow& block) {
    Impl& w = *impl_;
    const std::lock_guard<std::mutex> lock(w.mutex);
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x)
            w.published[std::size_t(y - w.window.y0) * std::size_t(w.window.width()) + std::size_t(x - w.window.x0)] =
                image.at(x, y);
    w.pending.push_back(block);
}

bool SdlWindow::showWhile(const std::function<bool()>& running) {
    // Test hook: $RT_TEST_SDL_CLOSE_MS closes the window that many milliseconds in, as the user would.
    const char* closeAfter = std::getenv("RT_TEST_SDL_CLOSE_MS");
    const Uint32 closeAt = closeAfter ? SDL_GetTicks() + Uint32(std::atoi(closeAfter)) : 0;
    SDL_Event e;
    while (running()) {
        if (closeAfter && SDL_TICKS_PASSED(SDL_GetTicks(), closeAt)) return false;
        if (SDL_WaitEventTimeout(&e, int(kFrameMs)) && closes(e)) return false;
        while (SDL_PollEvent(&e))
            if (closes(e)) return false;
        impl_->showPending();
    }
    return true;
}

void SdlWindow::showUntilClosed() {
    impl_->showPending();  // the last blocks
    if (const char* path = std::getenv("RT_TEST_SDL_DUMP")) return impl_->dump(path);
    SDL_Event e;
    while (SDL_WaitEvent(&e)) {
        if (closes(e)) return;
        if (e.type == SDL_WINDOWEVENT) impl_->showPending();  // exposed again: draw it again
    }
}

}  // namespace rt::tool::render

#else  // a build without SDL2

namespace rt::tool::render {

struct SdlWindow::Impl {};

bool SdlWindow::compiledIn() { return false; }

SdlWindow::SdlWindow(const PixelWindow&, const ColorSettings&, const std::string&) {
    throw InputError("-o sdl: this rt-render was built without SDL2 (install libsdl2-dev and rebuild)");
}

SdlWindow::~SdlWindow() = default;
void SdlWindow::publish(const Framebuffer&, const PixelWindow&) {}
bool SdlWindow::showWhile(const std::function<bool()>&) { return true; }
void SdlWindow::showUntilClosed() {}

}  // namespace rt::tool::render

#endif

namespace rt::tool::render {

int showWhileRendering(SdlWindow& window, const std::function<void(const RenderWatch&)>& work) {
    std::atomic<bool> stop{false}, finished{false};
    std::exception_ptr error;
    const RenderWatch watch{
        [&window](const Framebuffer& image, const PixelWindow& block) { window.publish(image, block); }, &stop, {}};
    std::thread worker([&] {
        try {
            work(watch);
        } catch (...) {
            error = std::current_exception();
        }
        finished = true;
    });
    const bool ranToTheEnd = window.showWhile([&finished] { return !finished; });
    stop = !ranToTheEnd;
    worker.join();
    if (error) std::rethrow_exception(error);
    if (!ranToTheEnd) return kExitStoppedByUser;
    window.showUntilClosed();
    return 0;
}

}  // namespace rt::tool::render
