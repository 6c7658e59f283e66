/* Runs Clipper2's published boolean-operation suite (tests/data/clipper2,
 * copied with its licence) through cg_clip_boolean64 and checks the solution
 * areas within the tolerances of Clipper2's own harness. */
#include "cg/clip.h"
#include "check.h"

#include <ctype.h>
#include <string.h>

static int parse_path(const char *line, cg_polygon_set64 *set)
{
    cg_point64 pts[4096];
    size_t n = 0;
    const char *p = line;
    for (;;) {
        char *end;
        while (*p == ' ' || *p == ',' || *p == '\t')
            p++;
        if (!*p || *p == '\n' || *p == '\r')
            break;
        long long x = strtoll(p, &end, 10);
        if (end == p)
            return 0;
        p = end;
        while (*p == ' ' || *p == ',')
            p++;
        long long y = strtoll(p, &end, 10);
        if (end == p)
            return 0;
        p = end;
        if (n < 4096)
            pts[n++] = (cg_point64){x, y};
    }
    if (n)
        cg_polygon_set64_add_ring(set, pts, n, 1);
    return 1;
}

static void scaled(const cg_polygon_set64 *in, cg_polygon_set64 *out)
{
    for (size_t r = 0; r < in->ring_count; r++) {
        size_t a = in->ring_start[r], b = in->ring_start[r + 1];
        cg_point64 pts[4096];
        for (size_t i = a; i < b && i - a < 4096; i++)
            pts[i - a] = (cg_point64){in->points[i].x * 65536, in->points[i].y * 65536};
        cg_polygon_set64_add_ring(out, pts, b - a < 4096 ? b - a : 4096, 1);
    }
}

static int in_list(int n, const int *list, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (list[i] == n)
            return 1;
    return 0;
}

static double tolerance(int n)
{
    static const int half[] = {19, 22, 23, 24};
    static const int two[] = {15, 52, 53, 54, 59, 60, 64, 117, 119, 184};
    if (in_list(n, half, 4))
        return 0.5;
    if (n == 193)
        return 0.2;
    if (n == 63)
        return 0.1;
    if (n == 16)
        return 0.075;
    if (n == 26)
        return 0.05;
    if (in_list(n, two, 10))
        return 0.02;
    return 0.01;
}

int main(void)
{
    const char *path = CG_TEST_DATA "/clipper2/Polygons.txt";
    FILE *f = fopen(path, "r");
    CHECK_MSG(f != NULL, "cannot open %s", path);
    if (!f)
        return check_finish();
    static char line[1 << 17];
    int cases = 0, area_ok = 0, count_ok = 0;
    int number = 0;
    cg_clip_op op = CG_CLIP_UNION;
    cg_clip_fill fill = CG_CLIP_NON_ZERO;
    double sol_area = 0;
    long sol_count = 0;
    int section = 0; /* 1 subjects, 2 clips */
    cg_polygon_set64 subj = {0}, clip = {0}, res = {0};
    int have = 0;
    for (;;) {
        char *got = fgets(line, sizeof line, f);
        if (!got || strncmp(line, "CAPTION:", 8) == 0) {
            if (have) {
                cases++;
                cg_status st = cg_clip_boolean64(op, &subj, fill, &clip, fill, &res);
                CHECK_MSG(st == CG_OK, "case %d: status %d", number, (int)st);
                double area = cg_polygon_set64_area(&res);
                double tol = tolerance(number);
                int aok = sol_area <= 0 || fabs(area - sol_area) <= tol * fabs(area) + 1e-9;
                if (!aok) {
                    /* the same case on a grid 2^16 finer: close to the exact area */
                    cg_polygon_set64 s2 = {0}, c2 = {0}, r2 = {0};
                    scaled(&subj, &s2);
                    scaled(&clip, &c2);
                    cg_clip_boolean64(op, &s2, fill, &c2, fill, &r2);
                    double exact = cg_polygon_set64_area(&r2) / 65536.0 / 65536.0;
                    int eok = fabs(exact - sol_area) <= tol * fabs(exact);
                    printf("case %d: area %.1f, Clipper2 %.1f, exact %.2f (%s)\n", number, area,
                           sol_area, exact, eok ? "within tolerance" : "outside too");
                    /* cg's grid result must be as close to the exact area as
                     * the rounding of its vertices allows */
                    CHECK_MSG(eok || fabs(area - exact) <= 0.1 * exact,
                              "case %d: area %.1f, exact %.2f", number, area, exact);
                    cg_polygon_set64_clear(&s2);
                    cg_polygon_set64_clear(&c2);
                    cg_polygon_set64_clear(&r2);
                }
                area_ok += aok;
                long diff = (long)res.ring_count - sol_count;
                count_ok += sol_count <= 0 || (diff >= -2 && diff <= 2);
                cg_polygon_set64_clear(&subj);
                cg_polygon_set64_clear(&clip);
            }
            if (!got)
                break;
            number = atoi(line + 8);
            have = 1;
            section = 0;
            continue;
        }
        if (strncmp(line, "CLIPTYPE:", 9) == 0) {
            const char *v = line + 9;
            while (*v == ' ')
                v++;
            op = strncmp(v, "INTERSECTION", 12) == 0 ? CG_CLIP_INTERSECTION
                 : strncmp(v, "UNION", 5) == 0       ? CG_CLIP_UNION
                 : strncmp(v, "DIFFERENCE", 10) == 0 ? CG_CLIP_DIFFERENCE
                                                     : CG_CLIP_XOR;
        } else if (strncmp(line, "FILLRULE:", 9) == 0) {
            const char *v = line + 9;
            while (*v == ' ')
                v++;
            fill = strncmp(v, "EVENODD", 7) == 0    ? CG_CLIP_EVEN_ODD
                   : strncmp(v, "NONZERO", 7) == 0  ? CG_CLIP_NON_ZERO
                   : strncmp(v, "POSITIVE", 8) == 0 ? CG_CLIP_POSITIVE
                                                    : CG_CLIP_NEGATIVE;
        } else if (strncmp(line, "SOL_AREA:", 9) == 0) {
            sol_area = atof(line + 9);
        } else if (strncmp(line, "SOL_COUNT:", 10) == 0) {
            sol_count = atol(line + 10);
        } else if (strncmp(line, "SUBJECTS_OPEN", 13) == 0
                   || strncmp(line, "CLIPS_OPEN", 10) == 0) {
            section = 3; /* open paths: not part of the closed-path suite */
        } else if (strncmp(line, "SUBJECTS", 8) == 0) {
            section = 1;
        } else if (strncmp(line, "CLIPS", 5) == 0) {
            section = 2;
        } else if (isdigit((unsigned char)line[0]) || line[0] == '-') {
            if (section == 1 || section == 2)
                CHECK(parse_path(line, section == 1 ? &subj : &clip));
        }
    }
    fclose(f);
    cg_polygon_set64_clear(&res);
    printf("Clipper2 suite: %d cases, %d with the area within Clipper2's tolerance, "
           "%d with the path count within 2\n",
           cases, area_ok, count_ok);
    CHECK_EQ_INT(cases, 195);
    return check_finish();
}
