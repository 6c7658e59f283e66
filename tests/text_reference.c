/* The helper of tests/test_draw_text.sh: what `cg draw`'s text commands
 * must give, computed with the library calls directly.
 *
 *   text_reference render OUT.ppm W H FONT SIZE X Y ALIGN BASELINE WIDTH SPACING TEXT
 *       the paragraph (cg_text_paragraph_path) filled black on white with
 *       the non-zero rule and curves within 0.01 px, as `cg draw` fills
 *       (binary PPM)
 *   text_reference measure FONT SIZE TEXT
 *       the advance width (cg_text_measure), %.17g
 *   text_reference breaks FONT SIZE WIDTH TEXT
 *       the lines of the greedy wrapping by the definition: words split at
 *       single spaces, a word joins the line while the line measured with it
 *       stays within WIDTH; one line per output line
 *
 * ALIGN is start|middle|end, BASELINE alphabetic|top|middle|bottom. */
#include "cg/fill.h"
#include "cg/image.h"
#include "cg/text.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage(void)
{
    fprintf(stderr, "usage: text_reference render|measure|breaks ... (see the source)\n");
    return 2;
}

static cg_font *load(const char *path)
{
    cg_font *font = NULL;
    cg_error err;
    if (cg_font_load(path, 0, &font, &err) != CG_OK) {
        fprintf(stderr, "text_reference: %s\n", err.message);
        return NULL;
    }
    return font;
}

static int word_index(const char *word, const char *const *words, int count)
{
    for (int i = 0; i < count; i++)
        if (strcmp(word, words[i]) == 0)
            return i;
    return -1;
}

static int render(char **argv)
{
    static const char *const aligns[] = {"start", "middle", "end"};
    static const char *const baselines[] = {"alphabetic", "top", "middle", "bottom"};
    int w = atoi(argv[1]), h = atoi(argv[2]);
    int align = word_index(argv[7], aligns, 3), baseline = word_index(argv[8], baselines, 4);
    cg_font *font = load(argv[3]);
    if (!font || align < 0 || baseline < 0)
        return 1;
    cg_text_paragraph style = {strtod(argv[4], NULL), strtod(argv[9], NULL), strtod(argv[10], NULL),
                               (cg_text_align)align, (cg_text_baseline)baseline};
    cg_image *image = NULL;
    cg_path *path = NULL;
    cg_rasterizer *rasterizer = NULL;
    cg_error err = {0};
    cg_paint black = cg_paint_solid((cg_rgba8){0, 0, 0, 255});
    cg_status status = cg_image_create(&image, w, h, CG_PIXEL_RGBA8);
    if (status == CG_OK)
        status = cg_path_create(&path);
    if (status == CG_OK)
        status = cg_rasterizer_create(&rasterizer);
    if (status == CG_OK) {
        cg_image_clear_rgba8(image, (cg_rgba8){255, 255, 255, 255});
        cg_rasterizer_set_tolerance(rasterizer, 0.01); /* as cg draw flattens glyphs */
        status = cg_text_paragraph_path(font, argv[11], &style, strtod(argv[5], NULL),
                                        strtod(argv[6], NULL), path, NULL, &err);
    }
    if (status == CG_OK)
        status = cg_rasterizer_fill_path(rasterizer, image, path, CG_FILL_NONZERO, &black);
    if (status == CG_OK)
        status = cg_image_write(image, argv[0], CG_FILE_UNKNOWN, &err);
    if (status != CG_OK)
        fprintf(stderr, "text_reference: %s %s\n", cg_status_str(status), err.message);
    cg_rasterizer_free(rasterizer);
    cg_path_free(path);
    cg_image_free(image);
    cg_font_free(font);
    return status != CG_OK;
}

static int measure(cg_font *font, double size, const char *text, double *width)
{
    cg_error err;
    if (cg_text_measure(font, text, size, width, &err) != CG_OK) {
        fprintf(stderr, "text_reference: %s\n", err.message);
        return 1;
    }
    return 0;
}

static int breaks(cg_font *font, double size, double width, char *text)
{
    char *line = malloc(strlen(text) + 1), *candidate = malloc(strlen(text) + 1);
    int failed = !line || !candidate;
    if (!failed)
        line[0] = '\0';
    for (char *word = strtok(text, " "); word && !failed; word = strtok(NULL, " ")) {
        double w;
        sprintf(candidate, "%s%s%s", line, *line ? " " : "", word);
        failed = measure(font, size, candidate, &w);
        if (!failed && *line && w > width) {
            printf("%s\n", line);
            strcpy(line, word);
        } else {
            strcpy(line, candidate);
        }
    }
    if (!failed && *line)
        printf("%s\n", line);
    free(line);
    free(candidate);
    return failed;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "render") == 0 && argc == 14)
        return render(argv + 2);
    if (argc == 5 && strcmp(argv[1], "measure") == 0) {
        cg_font *font = load(argv[2]);
        double width;
        int failed = !font || measure(font, strtod(argv[3], NULL), argv[4], &width);
        if (!failed)
            printf("%.17g\n", width);
        cg_font_free(font);
        return failed;
    }
    if (argc == 6 && strcmp(argv[1], "breaks") == 0) {
        cg_font *font = load(argv[2]);
        int failed = !font || breaks(font, strtod(argv[3], NULL), strtod(argv[4], NULL), argv[5]);
        cg_font_free(font);
        return failed;
    }
    return usage();
}
