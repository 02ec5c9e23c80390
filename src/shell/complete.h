/* complete.h: tab completion at the prompt, from the command table and the world.
 */
#ifndef VROC_COMPLETE_H
#define VROC_COMPLETE_H

#include "shell.h"

/* Makes readline complete statements for sh: commands, properties, object names,
 * and what may follow a command word. */
void complete_install(const shell *sh);

/* Frees the candidates kept between completions. */
void complete_free(void);

#endif
