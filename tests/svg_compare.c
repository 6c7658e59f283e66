/* Compares renderings of the same SVG files by cg and rsvg-convert with
 * resvg's (tests/test_svg_peers.sh).
 *
 * usage: svg_compare LIST CG_DIR RSVG_DIR RESVG_DIR [MARGIN]
 * LIST names the icons, one a line; the i-th (from 0) was rendered as i.png
 * in each folder.  An icon's difference is the mean over its pixels and the
 * four channels of |a - b| in codes (0..255) of the colours premultiplied by
 * alpha (what each would show over black), so transparent pixels compare
 * equal whatever colour they store.  An icon passes when cg's difference
 * from resvg is at most rsvg's difference from resvg plus MARGIN (default
 * 0.5 codes); the test passes when at least 99% of the icons resvg could
 * render pass.  The images are read with libpng through cg_image_read.
 *
 * usage: svg_compare --pair A.png B.png
 * prints "mean M touched T": the mean difference over the whole image and
 * over the pixels either image touches (alpha above 0), as for the text
 * drawings of tests/test_svg_text.sh, whose background is transparent. */
#include "cg/image.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cg_image *load(const char *dir, int index)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%d.png", dir, index);
    cg_image *image = NULL;
    if (cg_image_read(path, &image, NULL) != CG_OK)
        return NULL;
    return image;
}

/* The mean premultiplied difference, or -1 when the sizes differ; over
 * the pixels either touches when touched is not NULL (*touched: how many). */
static double difference_over(const cg_image *a, const cg_image *b, long *touched)
{
    if (a->width != b->width || a->height != b->height)
        return -1;
    double sum = 0;
    long count = 0;
    for (int y = 0; y < a->height; y++) {
        const cg_rgba8 *pa = cg_image_row_rgba8((cg_image *)a, y);
        const cg_rgba8 *pb = cg_image_row_rgba8((cg_image *)b, y);
        for (int x = 0; x < a->width; x++) {
            double ka = pa[x].a / 255.0, kb = pb[x].a / 255.0;
            if (touched && pa[x].a == 0 && pb[x].a == 0)
                continue;
            count++;
            sum += fabs(pa[x].r * ka - pb[x].r * kb) + fabs(pa[x].g * ka - pb[x].g * kb)
                   + fabs(pa[x].b * ka - pb[x].b * kb) + abs(pa[x].a - pb[x].a);
        }
    }
    if (touched)
        *touched = count;
    return count ? sum / (4.0 * count) : 0;
}

static double difference(const cg_image *a, const cg_image *b)
{
    return difference_over(a, b, NULL);
}

static int pair(const char *path_a, const char *path_b)
{
    cg_image *a = NULL, *b = NULL;
    if (cg_image_read(path_a, &a, NULL) != CG_OK || cg_image_read(path_b, &b, NULL) != CG_OK) {
        fprintf(stderr, "svg_compare: cannot read %s or %s\n", path_a, path_b);
        cg_image_free(a);
        return 2;
    }
    long touched = 0;
    double whole = difference(a, b), over = difference_over(a, b, &touched);
    cg_image_free(a);
    cg_image_free(b);
    if (whole < 0) {
        fprintf(stderr, "svg_compare: %s and %s differ in size\n", path_a, path_b);
        return 2;
    }
    printf("mean %.4f touched %.4f pixels %ld\n", whole, over, touched);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "--pair") == 0)
        return pair(argv[2], argv[3]);
    if (argc < 5 || argc > 6) {
        fprintf(stderr, "usage: svg_compare LIST CG_DIR RSVG_DIR RESVG_DIR [MARGIN]\n");
        return 2;
    }
    double margin = argc == 6 ? atof(argv[5]) : 0.5;
    FILE *list = fopen(argv[1], "r");
    if (!list) {
        fprintf(stderr, "svg_compare: cannot open %s\n", argv[1]);
        return 2;
    }
    char name[4096];
    int index = 0, compared = 0, passed = 0, unrendered = 0;
    double cg_total = 0, rsvg_total = 0;
    while (fgets(name, sizeof name, list)) {
        name[strcspn(name, "\n")] = 0;
        cg_image *reference = load(argv[4], index);
        cg_image *ours = load(argv[2], index), *theirs = load(argv[3], index);
        if (!reference) {
            unrendered++; /* resvg refused it: nothing to compare with */
        } else {
            double cg = ours ? difference(ours, reference) : -1;
            double rsvg = theirs ? difference(theirs, reference) : -1;
            compared++;
            int ok = cg >= 0 && (rsvg < 0 || cg <= rsvg + margin);
            passed += ok;
            if (cg >= 0)
                cg_total += cg;
            if (rsvg >= 0)
                rsvg_total += rsvg;
            printf("%s %s cg %.3f rsvg %.3f\n", ok ? "ok  " : "MISS", name, cg, rsvg);
        }
        cg_image_free(reference);
        cg_image_free(ours);
        cg_image_free(theirs);
        index++;
    }
    fclose(list);
    if (compared == 0) {
        printf("svg_compare: nothing to compare\n");
        return 1;
    }
    double rate = 100.0 * passed / compared;
    printf("svg_compare: %d of %d icons within rsvg's difference + %.2f (%.1f%%; %d not "
           "rendered by resvg); mean difference from resvg: cg %.3f, rsvg %.3f codes\n",
           passed, compared, margin, rate, unrendered, cg_total / compared, rsvg_total / compared);
    return rate >= 99.0 ? 0 : 1;
}
