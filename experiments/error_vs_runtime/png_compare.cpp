// png_compare.cpp - compares two PNG images of the same size channel by channel (8-bit RGB).
// Prints one line: psnr_db max_abs_diff pixels_off_gt2 total_pixels
//   psnr_db         10 log10(255^2 / MSE) over all R, G, B samples; "inf" when identical
//   max_abs_diff    largest |a - b| over all samples (0..255)
//   pixels_off_gt2  pixels with some channel differing by more than 2 levels
//   total_pixels    width x height
// Exit status: 0 on success, 2 on an unreadable file or a size mismatch.
// The CMake target png_compare (BUILD/png_compare); the images are read by the kernel's
// rt_png_read, as every image torusrt writes is 8-bit RGB.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rt_png.h"

namespace {

struct Image {
    uint32_t width = 0, height = 0;
    std::vector<unsigned char> rgb;  // width * height * 3
};

bool read_png(const char *path, Image &img, std::string &err)
{
    uint8_t *rgb = nullptr;
    char msg[256] = "";
    if (rt_png_read(path, &img.width, &img.height, &rgb, msg, sizeof msg) != RT_OK) {
        err = msg;
        return false;
    }
    img.rgb.assign(rgb, rgb + static_cast<size_t>(img.width) * img.height * 3);
    std::free(rgb);
    return true;
}

}  // namespace

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s A.png B.png\nprints: psnr_db max_abs_diff pixels_off_gt2 total_pixels\n",
                     argv[0]);
        return 2;
    }
    Image a, b;
    std::string err;
    if (!read_png(argv[1], a, err) || !read_png(argv[2], b, err)) {
        std::fprintf(stderr, "png_compare: %s\n", err.c_str());
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "png_compare: sizes differ: %ux%u against %ux%u\n", a.width, a.height, b.width, b.height);
        return 2;
    }
    double sq = 0;
    int max_abs = 0;
    unsigned long long off = 0;
    size_t pixels = static_cast<size_t>(a.width) * a.height;
    for (size_t p = 0; p < pixels; p++) {
        int worst = 0;
        for (int c = 0; c < 3; c++) {
            int d = std::abs(static_cast<int>(a.rgb[p * 3 + c]) - static_cast<int>(b.rgb[p * 3 + c]));
            sq += static_cast<double>(d) * d;
            if (d > worst) worst = d;
        }
        if (worst > max_abs) max_abs = worst;
        if (worst > 2) off++;
    }
    if (sq == 0) std::printf("inf");
    else std::printf("%.4f", 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(pixels) * 3.0 / sq));
    std::printf(" %d %llu %zu\n", max_abs, off, pixels);
    return 0;
}
