/* png_out.h: writing and reading 8-bit RGB PNG files with libpng.
 *
 * The writer is tuned for frame streams (design.md, "Performance"): a rendered
 * frame is mostly flat background and smooth shading, so the cheapest zlib effort
 * already compresses it 15 to 20 times, and encoding time, not file size, is what
 * limits the frame rate.  bench/bench_view.c measures the choices; png_write_rgb
 * uses the one it found fastest (png_out_default: zlib level 1, no PNG filter),
 * png_write_rgb_opts lets it try others.
 * The reader exists for the tests.  Sources: the PNG specification (filters, section
 * 9) and the libpng 1.6 manual (png_set_filter, png_set_compression_*).
 */
#ifndef VROC_PNG_OUT_H
#define VROC_PNG_OUT_H

#include <stddef.h>

/* How to compress: zlib level 0..9, a mask of libpng's PNG_FILTER_* (0 means
 * libpng's own default), and a zlib strategy (Z_DEFAULT_STRATEGY, Z_RLE, ...). */
typedef struct {
    int level;
    int filters;
    int strategy;
} png_out_opts;

/* The settings png_write_rgb uses. */
png_out_opts png_out_default(void);

/* Writes width x height 8-bit RGB pixels (rows top first, 3 * width bytes each, no
 * padding) to path, replacing the file.  Returns 0, or -1 with a message naming the
 * path in err (a partly written file is removed). */
int png_write_rgb(const char *path, const unsigned char *rgb, int width, int height,
                  char *err, size_t errlen);

/* png_write_rgb with explicit compression settings. */
int png_write_rgb_opts(const char *path, const unsigned char *rgb, int width, int height,
                       png_out_opts opts, char *err, size_t errlen);

/* Reads any PNG as 8-bit RGB (libpng converts grey, palette and alpha): *rgb gets a
 * malloc'd buffer of *w x *h x 3 bytes, rows top first, which the caller frees.
 * Returns 0, or -1 (then *rgb is NULL). */
int png_read_rgb(const char *path, unsigned char **rgb, int *w, int *h);

#endif
