/* Loads every OBJ, PLY, OFF and STL file under a directory (Debian's
 * assimp-testmodels: real files and deliberately broken ones).  Each must
 * either load into a mesh that validates or fail with a message that names
 * the file; files under a folder named "invalid" must fail.  A crash or a
 * sanitizer report fails the test.  Exit 77 (skipped) when the directory is
 * absent. */
#include "cg.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static int loaded, rejected, failures;

static int wanted(const char *name)
{
    const char *dot = strrchr(name, '.');
    return dot
           && (strcasecmp(dot, ".obj") == 0 || strcasecmp(dot, ".ply") == 0
               || strcasecmp(dot, ".off") == 0 || strcasecmp(dot, ".stl") == 0);
}

static void try_file(const char *path)
{
    cg_mesh *mesh = NULL;
    cg_error err;
    cg_error_clear(&err);
    cg_status status = cg_mesh_load(path, &mesh, &err);
    int must_fail = strstr(path, "/invalid/") != NULL;
    if (status == CG_OK) {
        cg_error check;
        if (!mesh || cg_mesh_validate(mesh, &check) != CG_OK) {
            printf("FAIL  %s: loaded a mesh that does not validate\n", path);
            failures++;
        } else if (must_fail) {
            printf("FAIL  %s: a broken file loaded (%zu vertices)\n", path, mesh->vertex_count);
            failures++;
        } else {
            printf("ok    %s: %zu vertices, %zu faces\n", path, mesh->vertex_count,
                   mesh->face_count);
            loaded++;
        }
    } else if (mesh || err.status != status || strncmp(err.message, path, strlen(path)) != 0) {
        printf("FAIL  %s: status %s without a message naming the file ('%s')\n", path,
               cg_status_str(status), err.message);
        failures++;
    } else {
        printf("error %s\n", err.message);
        rejected++;
    }
    cg_mesh_free(mesh);
}

static void walk(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *entry;
    char **names = NULL;
    size_t count = 0;
    while ((entry = readdir(d)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char **grown = realloc(names, (count + 1) * sizeof *names);
        if (!grown)
            break;
        names = grown;
        size_t n = strlen(dir) + strlen(entry->d_name) + 2;
        names[count] = malloc(n);
        snprintf(names[count++], n, "%s/%s", dir, entry->d_name);
    }
    closedir(d);
    for (size_t i = 0; i < count; i++) {
        struct stat st;
        if (stat(names[i], &st) == 0 && S_ISDIR(st.st_mode))
            walk(names[i]);
        else if (wanted(names[i]))
            try_file(names[i]);
        free(names[i]);
    }
    free(names);
}

int main(int argc, char **argv)
{
    /* The first argument that is a directory: CMake passes the one it found,
     * or every place the package installs to when it found none, so that a
     * package installed after the build is still found here. */
    const char *models = NULL;
    for (int i = 1; i < argc && !models; i++) {
        struct stat st;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode))
            models = argv[i];
    }
    if (!models) {
        printf("skipped: no assimp-testmodels directory (apt-get install assimp-testmodels)\n");
        return 77;
    }
    walk(models);
    printf("%d loaded, %d rejected with a clear error, %d failures\n", loaded, rejected, failures);
    return failures || loaded + rejected == 0 ? 1 : 0;
}
