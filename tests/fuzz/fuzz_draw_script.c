/* libFuzzer target: the `cg draw` script language (tools/cg/draw/draw_script.c
 * and every command group, tools/cg/draw/drawcmds_*.c): the text is tokenised
 * and run as `cg draw` runs it.  A script either draws a canvas or stops at
 * an error message; AddressSanitizer and UBSan check everything between
 * (number conversions, canvas bounds, the fill and stroke state).
 *
 * Scripts whose `size` asks for more than 2^20 pixels are skipped: they are
 * valid (up to 2^28), but only time memset.  The interpreter's messages go
 * to /dev/null unless FUZZ_VERBOSE is set, so a long run does not print
 * millions of them (sanitizer reports write to file descriptor 2 still). */
#include "draw_script_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (!getenv("FUZZ_VERBOSE")) {
        FILE *null = fopen("/dev/null", "w");
        if (null)
            stderr = null;
    }
    return 0;
}

static int too_large(const draw_script *script)
{
    for (int i = 0; i < script->count; i++) {
        const draw_line *line = &script->lines[i];
        if (strcmp(line->argv[0], "size") == 0 && line->argc == 3
            && strtod(line->argv[1], NULL) * strtod(line->argv[2], NULL) > (1 << 20))
            return 1;
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    draw_script script;
    if (draw_script_parse("fuzz.draw", text, &script) == 0) {
        if (!too_large(&script)) {
            draw_state state;
            int failed = draw_script_run(&script, &state);
            if (!failed && !state.canvas)
                abort();
            draw_state_release(&state);
        }
        draw_script_free(&script);
    }
    free(text);
    return 0;
}
