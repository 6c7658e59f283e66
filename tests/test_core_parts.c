/* The shared parts of src/core: the growable array's growth policy, its
 * refusal of sizes that overflow, and the typed array's macros. */
#include "../src/core/array.h"
#include "check.h"

#include <stdint.h>

static void growth_policy(void)
{
    int *data = NULL;
    size_t capacity = 0;
    CHECK(core_array_reserve((void **)&data, &capacity, 0, sizeof *data) == CG_OK);
    CHECK(data == NULL && capacity == 0);
    CHECK(core_array_reserve((void **)&data, &capacity, 1, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, CORE_ARRAY_FIRST);
    CHECK(core_array_reserve((void **)&data, &capacity, CORE_ARRAY_FIRST + 1, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, 2 * CORE_ARRAY_FIRST);
    CHECK(core_array_reserve((void **)&data, &capacity, 1000, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, 1024);
    for (int i = 0; i < 1000; i++)
        data[i] = i; /* the room is really there (the sanitizer build checks it) */
    size_t before = capacity;
    CHECK(core_array_reserve((void **)&data, &capacity, 10, sizeof *data) == CG_OK);
    CHECK_EQ_INT(capacity, before); /* never shrinks */
    free(data);
}

static void overflow_refused(void)
{
    char *data = NULL;
    size_t capacity = 0;
    CHECK(core_array_reserve((void **)&data, &capacity, 8, 1) == CG_OK);
    data[0] = 'x';
    size_t before = capacity;
    /* Bytes that do not fit in a size_t: refused, the array untouched. */
    CHECK(core_array_reserve((void **)&data, &capacity, SIZE_MAX / 2 + 1, 4) == CG_ENOMEM);
    CHECK(core_array_reserve((void **)&data, &capacity, SIZE_MAX, 2) == CG_ENOMEM);
    CHECK(core_array_reserve((void **)&data, &capacity, 100, 0) == CG_ENOMEM);
    CHECK_EQ_INT(capacity, before);
    CHECK(data[0] == 'x');
    free(data);
}

static void typed_array(void)
{
    CORE_ARRAY(double) values = {0};
    for (int i = 0; i < 100; i++)
        CHECK(core_array_push(&values, i * 0.5) == CG_OK);
    CHECK_EQ_INT(values.count, 100);
    CHECK(values.capacity >= 100);
    int same = 1;
    for (int i = 0; i < 100; i++)
        same &= values.data[i] == i * 0.5;
    CHECK(same);
    CHECK(core_array_reserve_for(&values, 500) == CG_OK);
    CHECK(values.capacity >= 500 && values.count == 100);
    core_array_free(&values);
    CHECK(values.data == NULL && values.count == 0 && values.capacity == 0);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(growth_policy);
    CHECK_GROUP(overflow_refused);
    CHECK_GROUP(typed_array);
    return check_finish();
}
