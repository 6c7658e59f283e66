/* Private to libcg: writing a file through a temporary beside it. */
#ifndef CG_SAFE_FILE_H
#define CG_SAFE_FILE_H

#include "cg/core.h"

#include <stdio.h>

typedef struct safe_file {
    FILE *file;      /* write here between open and close */
    char *temporary; /* the temporary file's name */
    const char *path;
} safe_file;

/* Creates the temporary file beside path (mode: the existing file's, or
 * 0666 less the umask), buffered for large writes. */
cg_status safe_file_open(safe_file *o, const char *path, cg_error *err);
/* Closes the file and, when status is CG_OK and every write succeeded,
 * renames it over path; otherwise removes it.  Returns the final status. */
cg_status safe_file_close(safe_file *o, cg_status status, cg_error *err);

#endif
