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
 * render pass.  The images are read with libpng through cg_image_read. */
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

/* The mean premultiplied difference, or -1 when the sizes differ. */
static double difference(const cg_image *a, const cg_image *b)
{
    if (a->width != b->width || a->height != b->height)
        return -1;
    double sum = 0;
    for (int y = 0; y < a->height; y++) {
        const cg_rgba8 *pa = cg_image_row_rgba8((cg_image *)a, y);
        const cg_rgba8 *pb = cg_image_row_rgba8((cg_image *)b, y);
        for (int x = 0; x < a->width; x++) {
            double ka = pa[x].a / 255.0, kb = pb[x].a / 255.0;
            sum += fabs(pa[x].r * ka - pb[x].r * kb) + fabs(pa[x].g * ka - pb[x].g * kb)
                   + fabs(pa[x].b * ka - pb[x].b * kb) + abs(pa[x].a - pb[x].a);
        }
    }
    return sum / (4.0 * a->width * a->height);
}

int main(int argc, char **argv)
{
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
