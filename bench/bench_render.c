/* Frames per second at 1920x1080: cg's z-buffer pipeline against Mesa's
 * software OpenGL through OSMesa (llvmpipe as Debian builds it), on the same
 * meshes, camera and light, flat and Gouraud shaded, on 1 and 2 threads.
 *
 * A frame is: clear colour and depth, transform, light, cull, clip and
 * rasterize every triangle, and (for OpenGL) glFinish.  Loading and normal
 * computation are outside the timing.  OpenGL draws indexed vertex arrays
 * with fixed-function lighting (one directional light plus ambient, no
 * specular); its flat mode lights the provoking vertex (glShadeModel
 * GL_FLAT), cg's lights the face normal.  llvmpipe reads its thread count
 * from LP_NUM_THREADS once per process, so each thread count of the peer is
 * measured in a child process. */
#include "bench.h"
#include "cg.h"

#include <string.h>
#include <time.h>
#include <sys/wait.h>
#include <unistd.h>

#ifdef CG_HAVE_OSMESA
#include <GL/osmesa.h>
#include <GL/gl.h>
#include "../tests/gl_camera.h"
#endif

#define WIDTH 1920
#define HEIGHT 1080
#define MAX_SCENES 8

typedef struct scene {
    char name[48];
    cg_mesh *mesh;
    size_t triangles;
} scene;

static int load_scenes(scene *s)
{
    int n = 0;
    static const char *files[] = {"teapot.obj", "bunny.obj", "dragon_vrip_res4.ply.gz",
                                  "dragon_vrip_res3.ply.gz"};
    for (int i = 0; i < 4; i++) {
        char path[1024];
        cg_error err;
        snprintf(path, sizeof path, "%s/data/meshes/%s", CG_SOURCE_DIR, files[i]);
        if (cg_mesh_load(path, &s[n].mesh, &err) != CG_OK) {
            fprintf(stderr, "bench_render: %s\n", err.message);
            continue;
        }
        snprintf(s[n].name, sizeof s[n].name, "%s", files[i]);
        n++;
    }
    /* Generated spheres with 100k and 1M triangles, a torus with 250k. */
    if (cg_mesh_sphere(316, 159, 1, &s[n].mesh) == CG_OK)
        snprintf(s[n++].name, sizeof s[n].name, "sphere");
    if (cg_mesh_torus(500, 250, 1, 0.4, &s[n].mesh) == CG_OK)
        snprintf(s[n++].name, sizeof s[n].name, "torus");
    if (cg_mesh_sphere(1000, 501, 1, &s[n].mesh) == CG_OK)
        snprintf(s[n++].name, sizeof s[n].name, "sphere");
    for (int i = 0; i < n; i++)
        s[i].triangles = cg_mesh_triangle_count(s[i].mesh);
    return n;
}

static cg_render_options scene_options(cg_shading shading, int threads)
{
    cg_render_options o;
    cg_render_options_default(&o);
    o.camera.eye = cg_vec3_make(0.3, 0.2, 1);
    o.shading = shading;
    o.specular = 0;
    o.ambient = 0.2;
    o.light_count = 1;
    o.lights[0].direction = cg_vec3_make(-0.4, 0.7, 0.6);
    o.lights[0].intensity = 0.9;
    o.threads = threads;
    o.color = (cg_rgbaf){0.5f, 0.45f, 0.3f, 1};
    o.background = (cg_rgbaf){0, 0, 0, 1};
    return o;
}

/* Median wall time, and the median process CPU time per run in *cpu (all
 * threads of the process together; steadier than wall time on a loaded
 * machine). */
static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double timed(void (*work)(void *), void *context, int runs, double *cpu)
{
    double wall[64], used[64];
    if (runs > 64)
        runs = 64;
    for (int i = 0; i < runs; i++) {
        double c = cpu_now(), w = bench_now();
        work(context);
        wall[i] = bench_now() - w;
        used[i] = cpu_now() - c;
    }
    qsort(wall, (size_t)runs, sizeof wall[0], bench_compare);
    qsort(used, (size_t)runs, sizeof used[0], bench_compare);
    *cpu = used[runs / 2];
    return wall[runs / 2];
}

static int runs_for(size_t triangles)
{
    return triangles > 500000 ? 5 : triangles > 50000 ? 9 : 15;
}

typedef struct cg_job {
    cg_renderer *renderer;
    cg_image *image;
} cg_job;

static void cg_frame(void *context)
{
    cg_job *j = context;
    cg_renderer_draw(j->renderer, j->image);
    bench_sink = j->image->data[WIDTH * 4 * (HEIGHT / 2) + WIDTH * 2];
}

#ifdef CG_HAVE_OSMESA
typedef struct gl_job {
    GLsizei count;
    const GLuint *indices;
} gl_job;

static void gl_frame(void *context)
{
    gl_job *j = context;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, j->count, GL_UNSIGNED_INT, j->indices);
    glFinish();
}

/* Times every scene and shading in OpenGL with the current LP_NUM_THREADS;
 * writes one line "seconds" per case to out. */
static void gl_measure(scene *scenes, int count, FILE *out)
{
    unsigned char *buffer = malloc((size_t)WIDTH * HEIGHT * 4);
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!context || !buffer
        || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
        for (int i = 0; i < count * 2; i++)
            fprintf(out, "0 0\n");
        return;
    }
    fprintf(stderr, "bench_render: OpenGL renderer: %s\n", (const char *)glGetString(GL_RENDERER));
    for (int i = 0; i < count; i++) {
        cg_mesh *m = scenes[i].mesh;
        /* Vertex arrays with the corner normals cg computes (crease 60 deg);
         * corners are unshared, as cg's own split does at creases. */
        size_t corners = m->face_offsets[m->face_count];
        cg_vec3 *normals = malloc(sizeof *normals * corners);
        float *positions = malloc(sizeof(float) * 3 * corners);
        float *normal_array = malloc(sizeof(float) * 3 * corners);
        GLuint *indices = malloc(sizeof(GLuint) * 3 * scenes[i].triangles);
        cg_render_options o = scene_options(CG_SHADING_GOURAUD, 1);
        cg_mesh_corner_normals(m, o.crease_angle, normals);
        for (size_t k = 0; k < corners; k++) {
            cg_vec3 p = m->positions[m->face_indices[k]];
            positions[3 * k] = (float)p.x;
            positions[3 * k + 1] = (float)p.y;
            positions[3 * k + 2] = (float)p.z;
            normal_array[3 * k] = (float)normals[k].x;
            normal_array[3 * k + 1] = (float)normals[k].y;
            normal_array[3 * k + 2] = (float)normals[k].z;
        }
        size_t t = 0;
        for (size_t f = 0; f < m->face_count; f++)
            for (uint32_t k = m->face_offsets[f] + 1; k + 1 < m->face_offsets[f + 1]; k++) {
                indices[t++] = m->face_offsets[f];
                indices[t++] = k;
                indices[t++] = k + 1;
            }
        /* The camera cg frames for this mesh. */
        cg_renderer *r;
        cg_image *probe;
        cg_renderer_create(m, &o, &r, NULL);
        cg_image_create(&probe, 16, 9, CG_PIXEL_RGBA8);
        cg_renderer_draw(r, probe);
        cg_camera camera = cg_renderer_camera(r);
        cg_renderer_free(r);
        cg_image_free(probe);
        GLdouble mat[16];
        gl_load_camera(&camera, WIDTH, HEIGHT, 1, mat);
        /* The light direction is given in world space: set it with the
         * identity, then load the view. */
        GLfloat direction[4] = {(GLfloat)o.lights[0].direction.x, (GLfloat)o.lights[0].direction.y,
                                (GLfloat)o.lights[0].direction.z, 0};
        GLfloat white[4] = {0.9f, 0.9f, 0.9f, 1}, none[4] = {0, 0, 0, 1};
        GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1};
        GLfloat color[4] = {o.color.r, o.color.g, o.color.b, 1};
        glLightfv(GL_LIGHT0, GL_POSITION, direction);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
        glLightfv(GL_LIGHT0, GL_SPECULAR, none);
        glLightfv(GL_LIGHT0, GL_AMBIENT, none);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, color);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
        glLoadMatrixd(mat);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glCullFace(GL_BACK);
        glClearColor(0, 0, 0, 1);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, positions);
        glNormalPointer(GL_FLOAT, 0, normal_array);
        gl_job job = {(GLsizei)t, indices};
        for (int shading = 0; shading < 2; shading++) {
            glShadeModel(shading == 0 ? GL_FLAT : GL_SMOOTH);
            gl_frame(&job); /* warm-up */
            double cpu, wall = timed(gl_frame, &job, runs_for(scenes[i].triangles), &cpu);
            fprintf(out, "%.9g %.9g\n", wall, cpu);
            fflush(out);
        }
        free(normals);
        free(positions);
        free(normal_array);
        free(indices);
    }
    OSMesaDestroyContext(context);
    free(buffer);
}

/* Runs gl_measure in a child with LP_NUM_THREADS set; fills seconds. */
static int gl_child(scene *scenes, int count, int threads, double *seconds, double *cpu)
{
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0)
        return -1;
    fflush(NULL);
    pid_t child = fork();
    if (child < 0)
        return -1;
    if (child == 0) {
        close(pipe_ends[0]);
        char value[16];
        snprintf(value, sizeof value, "%d", threads);
        setenv("LP_NUM_THREADS", value, 1);
        FILE *out = fdopen(pipe_ends[1], "w");
        gl_measure(scenes, count, out);
        fclose(out);
        _exit(0);
    }
    close(pipe_ends[1]);
    FILE *in = fdopen(pipe_ends[0], "r");
    for (int i = 0; i < count * 2; i++)
        if (fscanf(in, "%lf %lf", &seconds[i], &cpu[i]) != 2)
            seconds[i] = cpu[i] = 0;
    fclose(in);
    waitpid(child, NULL, 0);
    return 0;
}
#endif

int main(void)
{
    scene scenes[MAX_SCENES];
    int count = load_scenes(scenes);
    cg_image *image;
    cg_image_create(&image, WIDTH, HEIGHT, CG_PIXEL_RGBA8);
    for (int threads = 1; threads <= 2; threads++) {
        double peer[MAX_SCENES * 2] = {0}, peer_cpu[MAX_SCENES * 2] = {0};
#ifdef CG_HAVE_OSMESA
        gl_child(scenes, count, threads, peer, peer_cpu);
#endif
        for (int i = 0; i < count; i++)
            for (int shading = 0; shading < 2; shading++) {
                cg_render_options o = scene_options(shading ? CG_SHADING_GOURAUD : CG_SHADING_FLAT,
                                                    threads);
                cg_renderer *r;
                if (cg_renderer_create(scenes[i].mesh, &o, &r, NULL) != CG_OK)
                    continue;
                cg_job job = {r, image};
                cg_frame(&job);
                double cpu, t = timed(cg_frame, &job, runs_for(scenes[i].triangles), &cpu);
                cg_renderer_free(r);
                char name[256], note[160];
                snprintf(name, sizeof name, "render 1920x1080 %.40s %zuk tri %s %dT",
                         scenes[i].name, (scenes[i].triangles + 500) / 1000,
                         shading ? "gouraud" : "flat", threads);
                double p = peer[i * 2 + shading], pc = peer_cpu[i * 2 + shading];
                if (p > 0)
                    snprintf(note, sizeof note,
                             "%.1f vs %.1f fps; CPU per frame cg %.1f ms, llvmpipe %.1f ms", 1 / t,
                             1 / p, cpu * 1e3, pc * 1e3);
                else
                    snprintf(note, sizeof note, "%.1f fps; CPU per frame %.1f ms", 1 / t,
                             cpu * 1e3);
                if (p > 0)
                    bench_row(name, t, "osmesa", p, note);
                else
                    bench_row(name, t, "-", 0, "OSMesa not available");
                fprintf(stderr, "    %s\n", note);
            }
    }
    /* Multisampling: 4 samples per pixel against cg's own one sample (the
     * "peer" column), Gouraud, 1 thread.  OSMesa offers no multisample
     * buffers, so llvmpipe has no 4x row here. */
    for (int i = 0; i < count; i++) {
        double seconds[2] = {0, 0}, cpu[2] = {0, 0};
        for (int k = 0; k < 2; k++) {
            cg_render_options o = scene_options(CG_SHADING_GOURAUD, 1);
            o.msaa = k ? 4 : 1;
            cg_renderer *r;
            if (cg_renderer_create(scenes[i].mesh, &o, &r, NULL) != CG_OK)
                break;
            cg_job job = {r, image};
            cg_frame(&job);
            seconds[k] = timed(cg_frame, &job, runs_for(scenes[i].triangles), &cpu[k]);
            cg_renderer_free(r);
        }
        if (!(seconds[0] > 0 && seconds[1] > 0))
            continue;
        char name[256], note[160];
        snprintf(name, sizeof name, "render 1920x1080 %.40s %zuk tri gouraud msaa 4x 1T",
                 scenes[i].name, (scenes[i].triangles + 500) / 1000);
        snprintf(note, sizeof note,
                 "peer: cg at 1 sample; cost of 4x %.2fx wall, %.2fx CPU (%.1f vs %.1f ms)",
                 seconds[1] / seconds[0], cpu[1] / cpu[0], cpu[1] * 1e3, cpu[0] * 1e3);
        bench_row(name, seconds[1], "cg-1x", seconds[0], note);
        fprintf(stderr, "    %s\n", note);
    }
    cg_image_free(image);
    for (int i = 0; i < count; i++)
        cg_mesh_free(scenes[i].mesh);
    return 0;
}
