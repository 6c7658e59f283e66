/* Gallery: text (chapter 2) - runs in several scripts (Latin, Greek,
 * Arabic and Hebrew right to left, Devanagari, Thai, CJK when a font has
 * it), alignment and baselines, and a paragraph wrapped to a width, each a
 * `cg draw` script of `font` and `text` lines. */
#include "demo.h"
#include "script_pictures.h"
#include "cg/text.h"

#include <stdio.h>

/* A family fontconfig has: a script line in a missing family is left out,
 * so the gallery draws on any machine. */
static int installed(const char *family)
{
    return cg_font_family_exists(family, NULL) == CG_OK;
}

typedef struct script_sample {
    const char *script; /* its name, the label */
    const char *family;
    const char *text;
    const char *note; /* what the shaper does there */
} script_sample;

static int scripts(demo_context *context)
{
    static const script_sample samples[] = {
        {"Latin", "DejaVu Serif", "Affine office, AVA Wa", "ligatures ffi fi, kerning AV Wa"},
        {"Greek", "DejaVu Sans",
         "\xce\x9a\xce\xb1\xce\xbb\xce\xb7\xce\xbc\xe1\xbd\xb3\xcf\x81\xce\xb1 "
         "\xce\xba\xe1\xbd\xb9\xcf\x83\xce\xbc\xce\xb5",
         "precomposed accents"},
        {"Arabic", "Noto Sans Arabic",
         "\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7 \xd8\xa8\xd8\xa7\xd9\x84\xd8\xb9\xd8\xa7\xd9\x84"
         "\xd9\x85",
         "right to left, joining forms"},
        {"Hebrew", "Noto Sans Hebrew",
         "\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d \xd7\xa2\xd7\x95\xd7\x9c\xd7\x9d", "right to left"},
        {"Devanagari", "Noto Sans Devanagari",
         "\xe0\xa4\xa8\xe0\xa4\xae\xe0\xa4\xb8\xe0\xa5\x8d\xe0\xa4\xa4\xe0\xa5\x87 "
         "\xe0\xa4\xa6\xe0\xa5\x81\xe0\xa4\xa8\xe0\xa4\xbf\xe0\xa4\xaf\xe0\xa4\xbe",
         "conjuncts, reordered vowel signs"},
        {"Thai", "Noto Sans Thai",
         "\xe0\xb8\xaa\xe0\xb8\xa7\xe0\xb8\xb1\xe0\xb8\xaa\xe0\xb8\x94\xe0\xb8\xb5"
         "\xe0\xb8\x8a\xe0\xb8\xb2\xe0\xb8\xa7\xe0\xb9\x82\xe0\xb8\xa5\xe0\xb8\x81",
         "stacked marks"},
        {"CJK", "Noto Sans CJK SC", "\xe4\xbd\xa0\xe5\xa5\xbd\xef\xbc\x8c\xe4\xb8\x96\xe7\x95\x8c",
         "ideographs"},
    };
    if (!installed("DejaVu Sans") || !installed("DejaVu Serif"))
        return 0; /* no fonts-dejavu-core: nothing to show */
    int shown = 0;
    for (size_t i = 0; i < sizeof samples / sizeof *samples; i++)
        shown += installed(samples[i].family);
    sketch k = {0};
    sketch_add(&k, "# one run per script: shaped by HarfBuzz, filled by cg\n");
    sketch_add(&k, "size 640 %d\nbackground #faf8f2\n", 24 + 56 * (shown ? shown : 1));
    int row = 0;
    for (size_t i = 0; i < sizeof samples / sizeof *samples; i++) {
        const script_sample *s = &samples[i];
        if (!installed(s->family))
            continue;
        int y = 56 + 56 * row++;
        sketch_add(&k, "color #8a8a90\nfont DejaVu Sans 12\ntext 16 %d %s\n", y - 14, s->script);
        sketch_add(&k, "text 16 %d \"%s\"\n", y + 2, s->note);
        sketch_add(&k, "color #282830\nfont %s 30\ntext 230 %d \"%s\"\n", s->family, y, s->text);
        sketch_add(&k, "color #d8d4cc\naaline 230 %d.5 620 %d.5\n", y, y);
    }
    return draw_demo_sketch(context, &k, "text-scripts",
                            "Text in several scripts: each run shaped by HarfBuzz (ligatures and "
                            "kerning, Arabic and Hebrew right to left with joining forms, "
                            "Devanagari conjuncts and reordering, Thai marks; CJK when a font "
                            "has it), its FreeType outlines filled by cg's exact-area rasterizer; "
                            "the grey line is the baseline");
}

static int layout(demo_context *context)
{
    static const char *const aligns[] = {"start", "middle", "end"};
    static const char *const baselines[] = {"alphabetic", "top", "middle", "bottom"};
    if (!installed("DejaVu Sans") || !installed("DejaVu Serif"))
        return 0;
    sketch k = {0};
    sketch_add(&k, "# alignment, baselines and a wrapped paragraph\n");
    sketch_add(&k, "size 640 330\nbackground #faf8f2\n");
    sketch_add(&k, "color #3a76be\naaline 160.5 10 160.5 120\n");
    for (int i = 0; i < 3; i++) {
        int y = 40 + 34 * i;
        sketch_add(&k, "color #d8d4cc\naaline 20 %d.5 300 %d.5\n", y, y);
        sketch_add(&k, "color #282830\nfont DejaVu Sans 22\nalign %s\ntext 160 %d align %s\n",
                   aligns[i], y, aligns[i]);
    }
    sketch_add(&k, "align start\n");
    for (int i = 0; i < 4; i++) {
        int x = 330 + 74 * i;
        sketch_add(&k, "color #d65c3e\naaline %d 60.5 %d 60.5\n", x, x + 66);
        sketch_add(&k, "color #282830\nfont DejaVu Serif 26\nbaseline %s\ntext %d 60 Hxg\n",
                   baselines[i], x + 2);
        sketch_add(&k, "color #8a8a90\nfont DejaVu Sans 10\nbaseline alphabetic\ntext %d 110 %s\n",
                   x + 2, baselines[i]);
    }
    sketch_add(&k, "color #3a76be\naaline 20.5 140 20.5 320\naaline 420.5 140 420.5 320\n"
                   "aaline 620.5 140 620.5 320\n");
    sketch_add(&k, "color #282830\nfont DejaVu Serif 17\nwrap 400\nlinespacing 1.4\n"
                   "text 20 166 A paragraph is split at spaces and each line takes the most "
                   "words whose shaped width fits the 400 pixels between the blue lines: "
                   "kerning and ligatures count, so the break falls where the glyphs "
                   "really end.\n");
    sketch_add(&k, "color #8a8a90\nfont DejaVu Sans 11\nwrap 180\nlinespacing 1.3\nalign end\n"
                   "text 440 166 The same paragraph rules, right-aligned to the 180 pixels from x "
                   "= 440 to 620: "
                   "each line ends on the edge.\n");
    return draw_demo_sketch(context, &k, "text-layout",
                            "Text layout: align start, middle and end on the blue line (each run "
                            "moved by its measured advance), the four baselines against the red "
                            "lines, and paragraphs wrapped to a width with line spacing");
}

static int render(demo_context *context)
{
    int failed = scripts(context);
    failed |= layout(context);
    return failed;
}

const demo_section demo_section_text = {2, "Text: fonts, shaping and layout", render};
