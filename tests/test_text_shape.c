/* Shaped runs (cg_text_shape) against HarfBuzz's own hb-shape tool on the
 * same font files: glyph ids, clusters, advances and offsets identical for
 * Latin with kerning and ligatures, Arabic and Devanagari. */
#include "cg/text.h"
#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct shape_case {
    const char *font, *text;
} shape_case;

static const shape_case cases[] = {
    {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "office AVA To. Wolf fi ffl"},
    {"/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf", "Yes, WAVE: difficult efficiency"},
    {"/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf", "Te Va LT fi x\xcc\x81 \xc3\xa9"},
    {"/usr/share/fonts/truetype/noto/NotoSansArabic-Regular.ttf",
     "\xd8\xa8\xd8\xb3\xd9\x85 \xd8\xa7\xd9\x84\xd9\x84\xd9\x87 \xd8\xb3\xd9\x84\xd8\xa7\xd9\x85"},
    {"/usr/share/fonts/truetype/noto/NotoNaskhArabic-Regular.ttf",
     "\xd9\x84\xd8\xa7 \xd9\x85\xd9\x8e\xd8\xb1\xd9\x92\xd8\xad\xd9\x8e\xd8\xa8\xd9\x8b\xd8\xa7"},
    {"/usr/share/fonts/truetype/noto/NotoSansDevanagari-Regular.ttf",
     "\xe0\xa4\xb9\xe0\xa4\xbf\xe0\xa4\x82\xe0\xa4\xa6\xe0\xa5\x80 \xe0\xa4\x95\xe0\xa5\x8d"
     "\xe0\xa4\xb7\xe0\xa4\xa4\xe0\xa5\x8d\xe0\xa4\xb0\xe0\xa4\xbf\xe0\xa4\xaf"},
};

/* Reads hb-shape's JSON glyphs: {"g":N,"cl":N,"dx":N,"dy":N,"ax":N,"ay":N}. */
static size_t parse_json(const char *s, cg_shaped_glyph *out, size_t cap)
{
    size_t n = 0;
    const char *p = s;
    while (n < cap && (p = strstr(p, "{\"g\":")) != NULL) {
        int g, cl, dx, dy, ax, ay;
        if (sscanf(p, "{\"g\":%d,\"cl\":%d,\"dx\":%d,\"dy\":%d,\"ax\":%d,\"ay\":%d}", &g, &cl, &dx,
                   &dy, &ax, &ay)
            != 6)
            break;
        out[n++] = (cg_shaped_glyph){(unsigned)g, (unsigned)cl, ax, ay, dx, dy};
        p++;
    }
    return n;
}

static void matches_hb_shape(void)
{
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        FILE *probe = fopen(cases[c].font, "rb");
        if (!probe) {
            printf("  %s missing (apt-get install fonts-noto-core): case skipped\n", cases[c].font);
            continue;
        }
        fclose(probe);
        char text_file[] = "/tmp/cg_text_shape_XXXXXX";
        int fd = mkstemp(text_file);
        FILE *tf = fd >= 0 ? fdopen(fd, "w") : NULL;
        CHECK(tf != NULL);
        if (!tf)
            continue;
        fputs(cases[c].text, tf);
        fclose(tf);
        char command[1024];
        snprintf(command, sizeof command,
                 "hb-shape --utf8-clusters --no-glyph-names --output-format=json --text-file=%s %s",
                 text_file, cases[c].font);
        FILE *pipe = popen(command, "r");
        static char output[65536];
        size_t got = pipe ? fread(output, 1, sizeof output - 1, pipe) : 0;
        output[got] = '\0';
        if (pipe)
            pclose(pipe);
        remove(text_file);
        static cg_shaped_glyph expected[1024];
        size_t want = parse_json(output, expected, 1024);
        cg_font *font = NULL;
        cg_shaped_glyph *glyphs = NULL;
        size_t n = 0;
        cg_error err;
        CHECK_MSG(cg_font_load(cases[c].font, 0, &font, &err) == CG_OK, "%s", err.message);
        CHECK(font && cg_text_shape(font, cases[c].text, (size_t)-1, &glyphs, &n, &err) == CG_OK);
        CHECK_MSG(want > 0 && n == want, "%s: cg %zu glyphs, hb-shape %zu", cases[c].font, n, want);
        size_t same = 0;
        for (size_t i = 0; i < n && i < want; i++) {
            if (glyphs[i].glyph != expected[i].glyph || glyphs[i].x_offset != expected[i].x_offset
                || glyphs[i].y_offset != expected[i].y_offset
                || glyphs[i].x_advance != expected[i].x_advance)
                printf("  glyph %zu: cg %u@%d,%d+%d hb-shape %u@%d,%d+%d\n", i, glyphs[i].glyph,
                       glyphs[i].x_offset, glyphs[i].y_offset, glyphs[i].x_advance,
                       expected[i].glyph, expected[i].x_offset, expected[i].y_offset,
                       expected[i].x_advance);
            same += glyphs[i].glyph == expected[i].glyph && glyphs[i].cluster == expected[i].cluster
                    && glyphs[i].x_advance == expected[i].x_advance
                    && glyphs[i].y_advance == expected[i].y_advance
                    && glyphs[i].x_offset == expected[i].x_offset
                    && glyphs[i].y_offset == expected[i].y_offset;
        }
        CHECK_MSG(same == want, "%s: %zu of %zu glyphs identical", cases[c].font, same, want);
        printf("  %s: %zu glyphs identical to hb-shape\n", strrchr(cases[c].font, '/') + 1, same);
        free(glyphs);
        cg_font_free(font);
    }
}

int main(int argc, char **argv)
{
    if (system("hb-shape --version > /dev/null 2>&1") != 0) {
        printf("test_text_shape: hb-shape not found: skipped (apt-get install libharfbuzz-bin)\n");
        return 77;
    }
    if (system("test -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf") != 0) {
        printf("test_text_shape: DejaVu fonts not found: skipped (apt-get install "
               "fonts-dejavu-core)\n");
        return 77;
    }
    check_start(argc, argv);
    CHECK_GROUP(matches_hb_shape);
    return check_finish();
}
