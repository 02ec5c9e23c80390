/* savepath.h: how a saved world names the files it uses (a tracker file, a sound
 * file, a mesh file): relative to the saved file's folder when they lie under it,
 * absolute otherwise.  `read` takes a relative path in a file from that file's
 * folder, so the saved world finds its files from any current folder, and a
 * folder moved or copied whole with its saved worlds still works. */
#ifndef VROC_SAVEPATH_H
#define VROC_SAVEPATH_H

#include <stddef.h>

/* Writes into out (len bytes) the name of the file at path (absolute, or relative
 * to the current folder) as a world saved to save_file should write it: relative
 * to save_file's folder when the file lies under that folder, else absolute.
 * Symbolic links are followed on both sides when the files exist.  Returns out;
 * path itself when a name would not fit. */
const char *savepath(const char *path, const char *save_file, char *out, size_t len);

#endif
