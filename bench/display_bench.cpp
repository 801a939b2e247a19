// What showing one image in `vkphoton view` costs: the device-side display pass
// (view/display_pass.h: resolve, exposure, display transform by lattice, 8-bit pixels) against
// the host path the viewer used before it (read the film back, resolve, the PNG's exact display
// transform per pixel on one CPU thread). Per frame, median of --repeat, at --width x --height
// (default 1920x1080), for each --tonemap. The copy into the swapchain image and the present
// are the same for both and not timed.
// Usage: build/bench/display_bench [--width W --height H --repeat N --device D]
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/view_transform.h"
#include "median.h"
#include "render/film.h"
#include "util/stopwatch.h"
#include "view/display_pass.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton display benchmark"};
    uint32_t width = 1920, height = 1080, repeat = 5;
    std::string device;
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--repeat", repeat)->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        vk::Context context({false, device});
        // A film of log-uniform radiance over 24 stops around mid grey, 4 samples a pixel.
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> stops(-12.0f, 12.0f);
        std::vector<glm::vec4> sums(size_t(width) * height);
        for (glm::vec4& s : sums)
            s = glm::vec4(0.72f * std::exp2(stops(rng)), 0.72f * std::exp2(stops(rng)), 0.72f * std::exp2(stops(rng)), 4.0f);
        const vk::Buffer film = vk::makeStorageBuffer(context, "bench film", sums);
        fmt::print("display of a {}x{} film, device: {}, median of {}\n\n", width, height, context.deviceName(), repeat);
        fmt::print("| tonemap | lattice build, s | device pass, ms/frame | host path, ms/frame | host / device |\n");
        fmt::print("|---|---|---|---|---|\n");
        for (const auto& [name, view] : viewTransformChoices()) {
            auto start = Clock::now();
            const std::vector<glm::vec4> lattice = displayLattice(view);
            const double latticeSeconds = secondsSince(start);
            DisplayPass pass(context, width, height, lattice);
            std::vector<double> device, host;
            uint64_t checksum = 0;
            for (uint32_t r = 0; r < repeat; ++r) {
                start = Clock::now();
                context.submitAndWait([&](VkCommandBuffer cmd) { pass.record(cmd, film, nullptr, 4, 1.0f, false); });
                device.push_back(secondsSince(start));
                start = Clock::now();
                const ImageRgb image = resolveFilm(film.download<glm::vec4>(), width, height);
                std::vector<uint8_t> rgba(size_t(width) * height * 4, 255);
                DisplaySettings display;
                display.view = view;
                for (size_t i = 0; i < size_t(width) * height; ++i) {
                    const auto rgb = toDisplayBytes(
                        glm::vec3(image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]), display);
                    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = rgb[c];
                }
                host.push_back(secondsSince(start));
                checksum += rgba[4 * (size_t(r) * 7919 % (size_t(width) * height))];
            }
            const double d = bench::median(device), h = bench::median(host);
            fmt::print("| {} | {:.2f} | {:.1f} | {:.1f} | {:.0f}x |\n", name, latticeSeconds, 1e3 * d, 1e3 * h, h / d);
            if (checksum == 0xffffffffffffffffull) fmt::print("\n");  // keeps the host loop's result alive
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
