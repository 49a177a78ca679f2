// Image pairs for the metrics' tests (tests/compare/): generated deterministically, and a real render with
// doctored copies — the picture shifted by one pixel, the highlight smeared.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace shadelab::compare_test {

// A fresh empty folder under the temporary folder, unique to this process.
inline std::filesystem::path freshFolder(const std::string& what) {
    const auto folder =
        std::filesystem::temp_directory_path() / ("shadelab-" + what + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// Opaque noise from a fixed seed (a 32-bit LCG: the same pixels on every machine).
inline Image noise(int width, int height, std::uint32_t seed) {
    Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        seed = seed * 1664525u + 1013904223u;
        image.rgba[i] = (i % 4 == 3) ? 255 : std::uint8_t(seed >> 24);
    }
    return image;
}

// A grey-shaded disc on black, centre offset by `dx`; its edge anti-aliased by coverage of n×n samples per
// pixel (n = 1: aliased, a pixel is in or out).
inline Image shadedDisc(int width, int height, double dx, int samplesPerSide = 4) {
    Image image(width, height);
    const double cx = width / 2.0 + dx, cy = height / 2.0, r = std::min(width, height) * 0.35;
    const int n = samplesPerSide, samples = n * n;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            int covered = 0;
            for (int s = 0; s < samples; ++s) {
                const double sx = x + (s % n + 0.5) / n, sy = y + (s / n + 0.5) / n;
                covered += (sx - cx) * (sx - cx) + (sy - cy) * (sy - cy) < r * r;
            }
            const double coverage = double(covered) / samples;
            const double shade = 0.3 + 0.7 * std::clamp(1.0 - (x - cx + y - cy) / (3 * r), 0.0, 1.0);
            std::uint8_t* p = image.pixel(x, y);
            p[0] = std::uint8_t(std::lround(coverage * shade * 230));
            p[1] = std::uint8_t(std::lround(coverage * shade * 90));
            p[2] = std::uint8_t(std::lround(coverage * shade * 60));
            p[3] = 255;
        }
    return image;
}

// The image moved right by one pixel, its first column repeated.
inline Image shiftedRight(const Image& image) {
    Image out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 1; x < image.width; ++x) std::copy_n(image.pixel(x - 1, y), 4, out.pixel(x, y));
    return out;
}

// A 5x5 box blur of the pixels within `radius` of (cx, cy), the rest left as it is.
inline Image smeared(const Image& image, int cx, int cy, int radius) {
    Image out = image;
    for (int y = std::max(0, cy - radius); y <= std::min(image.height - 1, cy + radius); ++y)
        for (int x = std::max(0, cx - radius); x <= std::min(image.width - 1, cx + radius); ++x) {
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) > radius * radius) continue;
            for (int c = 0; c < 3; ++c) {
                int sum = 0, n = 0;
                for (int v = -2; v <= 2; ++v)
                    for (int u = -2; u <= 2; ++u) {
                        const int sx = std::clamp(x + u, 0, image.width - 1),
                                  sy = std::clamp(y + v, 0, image.height - 1);
                        sum += image.pixel(sx, sy)[c];
                        ++n;
                    }
                out.pixel(x, y)[c] = std::uint8_t((sum + n / 2) / n);
            }
        }
    return out;
}

// Where the render's highlight is: its brightest pixel (the first, in reading order).
inline std::pair<int, int> brightest(const Image& image) {
    int best = -1, bx = 0, by = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (p[0] + p[1] + p[2] > best) {
                best = p[0] + p[1] + p[2];
                bx = x;
                by = y;
            }
        }
    return {bx, by};
}

inline Image reference(const std::string& name) {
    return readPng(std::filesystem::path(SHADELAB_TEST_DATA) / "references" / (name + ".png"));
}
// The render the doctored pairs start from: a Phong-shaded sphere with a highlight (128x128).
inline Image phongRender() {
    return reference("phong_phong");
}
inline Image renderShifted() {
    return shiftedRight(phongRender());
}
inline Image renderSmeared() {
    const Image render = phongRender();
    const auto [x, y] = brightest(render);
    return smeared(render, x, y, 6);
}

struct Pair {
    std::string name;
    Image actual, expected;
    std::optional<Image> mask; // black: left out
};

// The pairs the metrics are held to their independent implementations on.
inline std::vector<Pair> independentPairs() {
    std::vector<Pair> pairs;
    pairs.push_back({"noise-64x48", noise(64, 48, 1), noise(64, 48, 2), std::nullopt});
    Image noisy = noise(64, 48, 3);
    Image slightly = noisy;
    for (std::size_t i = 0; i < slightly.rgba.size(); i += 7)
        slightly.rgba[i] = std::uint8_t(slightly.rgba[i] ^ 0x0f);
    pairs.push_back({"noise-perturbed", noisy, slightly, std::nullopt});
    pairs.push_back({"odd-13x11", noise(13, 11, 4), noise(13, 11, 5), std::nullopt});
    pairs.push_back({"disc-shifted", shadedDisc(48, 40, 0), shadedDisc(48, 40, 1), std::nullopt});
    pairs.push_back(
        {"disc-smeared", shadedDisc(48, 40, 0), smeared(shadedDisc(48, 40, 0), 24, 20, 9), std::nullopt});
    Image tinted = shadedDisc(48, 40, 0);
    for (std::size_t i = 0; i < tinted.rgba.size(); i += 4)
        tinted.rgba[i] = std::uint8_t(std::min(255, tinted.rgba[i] + 12));
    pairs.push_back({"disc-tinted", shadedDisc(48, 40, 0), tinted, std::nullopt});
    Image mask(48, 40);
    for (std::size_t i = 0; i < mask.rgba.size(); i += 4)
        mask.rgba[i] = mask.rgba[i + 3] = (i / 4) % 48 < 30 ? 255 : 0;
    pairs.push_back({"disc-shifted-masked", shadedDisc(48, 40, 0), shadedDisc(48, 40, 1), mask});
    pairs.push_back({"render-shifted", phongRender(), renderShifted(), std::nullopt});
    pairs.push_back({"render-smeared", phongRender(), renderSmeared(), std::nullopt});
    pairs.push_back({"disc-aliased", shadedDisc(64, 48, 0), shadedDisc(64, 48, 0, 1), std::nullopt});
    // An anti-aliased edge against the image's left border: black column, grey column, then noise; one grey
    // pixel darkened. Whether it is anti-aliasing hangs on the black column's pixels, which have two equal
    // neighbours and one more for being on the border (pixelmatch's hasManySiblings counts it).
    Image borderEdge = noise(24, 16, 6);
    for (int y = 0; y < borderEdge.height; ++y) {
        std::fill_n(borderEdge.pixel(0, y), 3, std::uint8_t(0));
        std::fill_n(borderEdge.pixel(1, y), 3, std::uint8_t(128));
    }
    Image borderEdgeDarkened = borderEdge;
    std::fill_n(borderEdgeDarkened.pixel(1, 8), 3, std::uint8_t(60));
    pairs.push_back({"aa-edge-at-border", borderEdge, borderEdgeDarkened, std::nullopt});
    // A second render, toon-shaded (flat bands with hard edges), its red raised by 60 (clamped) in a band
    // of rows across the picture: a colour shift beyond thresholds 0.05 and 0.1, within 0.3.
    const Image toon = reference("toon_blinn_phong");
    Image toonTinted = toon;
    for (int y = toon.height / 2; y < toon.height * 3 / 4; ++y)
        for (int x = 0; x < toon.width; ++x)
            toonTinted.pixel(x, y)[0] = std::uint8_t(std::min(255, toonTinted.pixel(x, y)[0] + 60));
    pairs.push_back({"toon-render-tinted", toon, toonTinted, std::nullopt});
    pairs.push_back({"toon-render-shifted", toon, shiftedRight(toon), std::nullopt});
    return pairs;
}

} // namespace shadelab::compare_test
