/* libFuzzer target: the WKT reader of `cg clip` (tools/cg/commands/clip_view.c),
 * then the boolean union the command runs on what it read, as `cg clip
 * boolean A B` does with an empty B.  A text that fails must say so with a
 * message naming it; one that parses must give a union that succeeds (or is
 * refused with CG_ERANGE for coordinates beyond the grid), and the union's
 * WKT, as the command prints it, must parse again into as many rings. */
#define _POSIX_C_SOURCE 200809L
#include "clip_view.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    cg_polygon_set set = {0}, empty = {0}, result = {0}, again = {0};
    cg_error err;
    cg_error_clear(&err);
    cg_status status = clip_wkt_parse(text, "fuzz", &set, &err);
    if (status != CG_OK) {
        if (err.status != status || strncmp(err.message, "fuzz", 4) != 0)
            abort();
        goto done;
    }
    status = cg_clip_boolean(CG_CLIP_UNION, &set, CG_CLIP_NON_ZERO, &empty, CG_CLIP_NON_ZERO, 0,
                             &result);
    if (status == CG_ERANGE || status == CG_ENOMEM)
        goto done;
    if (status != CG_OK)
        abort();
    char *written = NULL;
    size_t length = 0;
    FILE *out = open_memstream(&written, &length);
    if (!out)
        goto done;
    clip_wkt_write(out, &result);
    fclose(out);
    if (clip_wkt_parse(written, "written", &again, &err) != CG_OK
        || again.ring_count != result.ring_count) {
        fprintf(stderr, "the union's WKT does not read back: %s\n%s", err.message, written);
        abort();
    }
    free(written);
done:
    cg_polygon_set_clear(&set);
    cg_polygon_set_clear(&result);
    cg_polygon_set_clear(&again);
    free(text);
    return 0;
}
