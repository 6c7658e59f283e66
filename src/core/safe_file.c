/* Writing a file safely: to a temporary file beside the destination, renamed
 * over it only when complete, so a failure never leaves a truncated file or
 * replaces a good one.  Shared by the image and mesh writers. */
#include "safe_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The permissions a new file gets: an existing file's own, otherwise
 * 0666 less the process umask (read from /proc, since umask() cannot be read
 * without changing it), or 0644 where /proc is not there. */
static mode_t new_file_mode(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return st.st_mode & 07777;
    mode_t mode = 0644;
    FILE *status = fopen("/proc/self/status", "r");
    if (status) {
        char line[128];
        unsigned mask;
        while (fgets(line, sizeof line, status))
            if (sscanf(line, "Umask: %o", &mask) == 1) {
                mode = 0666 & ~(mode_t)mask;
                break;
            }
        fclose(status);
    }
    return mode;
}

cg_status safe_file_open(safe_file *o, const char *path, cg_error *err)
{
    size_t length = strlen(path);
    o->path = path;
    o->file = NULL;
    o->temporary = malloc(length + 16);
    if (!o->temporary)
        return cg_error_set(err, CG_ENOMEM, "%s: out of memory", path);
    memcpy(o->temporary, path, length);
    memcpy(o->temporary + length, ".tmp-XXXXXX", 12);
    int fd = mkstemp(o->temporary);
    if (fd >= 0)
        (void)fchmod(fd, new_file_mode(path)); /* mkstemp gives 0600 */
    if (fd >= 0 && !(o->file = fdopen(fd, "wb")))
        close(fd);
    if (!o->file) {
        cg_status s = cg_error_set(err, CG_EIO, "%s: cannot create a temporary file: %s", path,
                                   strerror(errno));
        if (fd >= 0)
            remove(o->temporary);
        free(o->temporary);
        o->temporary = NULL;
        return s;
    }
    setvbuf(o->file, NULL, _IOFBF, 1 << 16);
    return CG_OK;
}

/* Closes the file; renames it into place when ok, removes it otherwise. */
cg_status safe_file_close(safe_file *o, cg_status status, cg_error *err)
{
    if (!o->temporary)
        return status;
    int ok = status == CG_OK && !ferror(o->file);
    ok = fclose(o->file) == 0 && ok;
    if (ok)
        ok = rename(o->temporary, o->path) == 0;
    if (!ok) {
        if (status == CG_OK)
            status = cg_error_set(err, CG_EIO, "%s: cannot write: %s", o->path, strerror(errno));
        remove(o->temporary);
    }
    free(o->temporary);
    o->temporary = NULL;
    return status;
}
