/* errmsg.h: the core's failure messages, written into the caller's buffer: the
 * core prints nothing, and the layer above says them where it says everything
 * else. */
#ifndef VROC_ERRMSG_H
#define VROC_ERRMSG_H

#include <stddef.h>

/* Formats a message into err (errlen bytes, truncated to fit); nothing when err is
 * NULL or errlen 0, for callers that want no message. */
void errmsg_set(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
