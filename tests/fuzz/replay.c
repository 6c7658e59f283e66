/* Runs a fuzz target's LLVMFuzzerTestOneInput once on each file named on the
 * command line, and on each file of each directory named (in name order), as
 * libFuzzer would on its corpus, but in any build: the plain compiler, the
 * sanitizer build.  So every input of tests/fuzz/corpus/<name>/ (the seeds and
 * every input that ever failed) is checked by ctest without libFuzzer.  A
 * target reports a failure by aborting; this prints the file's name first. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

/* Reads the whole file; returns 0, or -1 with a message printed. */
static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return -1;
    }
    size_t size = 0, room = 4096;
    unsigned char *data = malloc(room);
    size_t got;
    while (data && (got = fread(data + size, 1, room - size, f)) > 0) {
        size += got;
        if (size == room) {
            unsigned char *bigger = realloc(data, room * 2);
            if (!bigger) {
                free(data);
                data = NULL;
                break;
            }
            data = bigger;
            room *= 2;
        }
    }
    int failed = ferror(f) || !data;
    fclose(f);
    if (failed) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        free(data);
        return -1;
    }
    printf("%s (%zu bytes)\n", path, size);
    fflush(stdout);
    LLVMFuzzerTestOneInput(data, size);
    free(data);
    return 0;
}

static int is_input(const struct dirent *entry)
{
    return entry->d_name[0] != '.';
}

int main(int argc, char **argv)
{
    int count = 0, errors = 0;
    for (int i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "replay: no file or directory %s\n", argv[i]);
            errors++;
        } else if (!S_ISDIR(st.st_mode)) {
            if (replay_file(argv[i]) == 0)
                count++;
            else
                errors++;
        } else {
            struct dirent **names;
            int n = scandir(argv[i], &names, is_input, alphasort);
            if (n < 0) {
                fprintf(stderr, "replay: cannot list %s\n", argv[i]);
                errors++;
                continue;
            }
            for (int k = 0; k < n; k++) {
                char path[4096];
                snprintf(path, sizeof path, "%s/%s", argv[i], names[k]->d_name);
                if (stat(path, &st) == 0 && S_ISREG(st.st_mode)) {
                    if (replay_file(path) == 0)
                        count++;
                    else
                        errors++;
                }
                free(names[k]);
            }
            free(names);
        }
    }
    printf("%d passed, %d failed\n", count, errors);
    return errors || count == 0 ? 1 : 0;
}
