/* png_out.c: fast PNG writing of rendered frames and a simple reader for the tests.
 *
 * The writer uses libpng's classic interface, which is the one that exposes the
 * zlib level, strategy and the PNG row filters; libpng reports errors by longjmp,
 * so the message is caught in a small context and turned into vroc's -1 + err.
 * The reader uses libpng 1.6's simplified png_image interface.
 */
#include "png_out.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "shell/outfile.h"

/* zlib level 1 without PNG filtering: measured fastest of levels 0 to 2 with the
 * none, sub, up and paeth filters and the default and RLE strategies (bench_view);
 * "up" gives files about a quarter smaller for 5 to 15 % more time. */
png_out_opts png_out_default(void)
{
    return (png_out_opts){.level = 1, .filters = PNG_FILTER_NONE, .strategy = Z_DEFAULT_STRATEGY};
}

/* libpng's error callback: keeps the message for the caller and unwinds.  A
 * failed write (libpng says only "Write Error") keeps the system's reason too. */
typedef struct {
    char msg[256];
    int errno_then; /* errno when libpng gave up */
} png_out_failure;

static void png_out_error(png_structp png, png_const_charp msg)
{
    png_out_failure *f = png_get_error_ptr(png);
    f->errno_then = errno;
    snprintf(f->msg, sizeof f->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void png_out_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* Compresses the rows into the open file fp.  Returns 0, or -1 with f->msg set. */
static int png_out_encode(FILE *fp, const unsigned char *rgb, int width, int height,
                          png_out_opts opts, png_out_failure *f)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, f, png_out_error,
                                              png_out_warning);
    if (!png) {
        snprintf(f->msg, sizeof f->msg, "out of memory");
        return -1;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(f->msg, sizeof f->msg, "out of memory");
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, fp);
    png_set_compression_level(png, opts.level);
    png_set_compression_strategy(png, opts.strategy);
    if (opts.filters) png_set_filter(png, PNG_FILTER_TYPE_BASE, opts.filters);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    size_t stride = (size_t)width * 3;
    for (int y = 0; y < height; y++) png_write_row(png, rgb + (size_t)y * stride);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int png_write_rgb_opts(const char *path, const unsigned char *rgb, int width, int height,
                       png_out_opts opts, char *err, size_t errlen)
{
    if (width <= 0 || height <= 0) {
        snprintf(err, errlen, "cannot write '%s': bad image size %dx%d", path, width, height);
        return -1;
    }
    /* written beside the file, and put in its place once whole (outfile.h) */
    outfile o;
    if (outfile_begin(&o, path, OUTFILE_STREAM, err, errlen) != 0) return -1;
    FILE *fp = o.f;
    setvbuf(fp, NULL, _IOFBF, 1 << 16);
    png_out_failure f = {{0}, 0};
    errno = 0;
    int rc = png_out_encode(fp, rgb, width, height, opts, &f);
    int saved = errno;
    if (rc != 0 && ferror(fp) && f.errno_then) /* the file failed, not the encoder */
        snprintf(f.msg, sizeof f.msg, "%s", strerror(f.errno_then));
    if (rc == 0 && ferror(fp)) {
        rc = -1;
        snprintf(f.msg, sizeof f.msg, "%s", strerror(saved ? saved : EIO));
    }
    if (rc != 0) {
        outfile_abort(&o);
        snprintf(err, errlen, "cannot write '%s': %s", path, f.msg);
        return -1;
    }
    return outfile_finish(&o, err, errlen);
}

int png_write_rgb(const char *path, const unsigned char *rgb, int width, int height,
                  char *err, size_t errlen)
{
    return png_write_rgb_opts(path, rgb, width, height, png_out_default(), err, errlen);
}

int png_read_rgb(const char *path, unsigned char **rgb, int *w, int *h)
{
    *rgb = NULL;
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) return -1;
    img.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf) {
        png_image_free(&img);
        return -1;
    }
    if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&img);
        return -1;
    }
    *rgb = buf;
    *w = (int)img.width;
    *h = (int)img.height;
    return 0;
}
