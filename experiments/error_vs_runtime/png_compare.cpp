// png_compare.cpp - compares two PNG images of the same size channel by channel (8-bit RGB).
// Prints one line: psnr_db max_abs_diff pixels_off_gt2 total_pixels
//   psnr_db         10 log10(255^2 / MSE) over all R, G, B samples; "inf" when identical
//   max_abs_diff    largest |a - b| over all samples (0..255)
//   pixels_off_gt2  pixels with some channel differing by more than 2 levels
//   total_pixels    width x height
// Exit status: 0 on success, 2 on an unreadable file or a size mismatch.
// Built by experiments/error_vs_runtime/common.sh:
//   g++ -O2 -std=c++17 png_compare.cpp -o png_compare $(pkg-config --cflags --libs libpng)
#include <png.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Image {
    png_uint_32 width = 0, height = 0;
    std::vector<unsigned char> rgb; // width * height * 3
};

bool read_png(const char *path, Image &img, std::string &err)
{
    std::FILE *f = std::fopen(path, "rb");
    if (!f) {
        err = std::string(path) + ": cannot open";
        return false;
    }
    unsigned char sig[8];
    if (std::fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        std::fclose(f);
        err = std::string(path) + ": not a PNG file";
        return false;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(f);
        err = "out of memory";
        return false;
    }
    std::vector<png_bytep> rows;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(f);
        err = std::string(path) + ": corrupt PNG";
        return false;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    int color = png_get_color_type(png, info);
    int depth = png_get_bit_depth(png, info);
    // Normalise every kind of PNG to 8-bit RGB.
    if (depth == 16) png_set_strip_16(png);
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    if (color & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_strip_alpha(png);
    png_read_update_info(png, info);
    img.width = png_get_image_width(png, info);
    img.height = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != static_cast<size_t>(img.width) * 3) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(f);
        err = std::string(path) + ": unsupported PNG layout";
        return false;
    }
    img.rgb.resize(static_cast<size_t>(img.width) * img.height * 3);
    rows.resize(img.height);
    for (png_uint_32 y = 0; y < img.height; y++) rows[y] = img.rgb.data() + static_cast<size_t>(y) * img.width * 3;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
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
        std::fprintf(stderr, "png_compare: sizes differ: %ux%u against %ux%u\n", a.width, a.height, b.width,
                     b.height);
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
