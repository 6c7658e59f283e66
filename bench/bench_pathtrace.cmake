# bench_pathtrace: the path tracer through the library, the command line and
# mpirun (when Open MPI is installed and cg was built with it: the rows say
# so when not).
add_executable(bench_pathtrace ${CMAKE_CURRENT_SOURCE_DIR}/bench_pathtrace.c)
target_compile_options(bench_pathtrace PRIVATE ${CG_WARNINGS})
target_compile_definitions(bench_pathtrace PRIVATE CG_TOOL="$<TARGET_FILE:cg>"
                                                   CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                   _POSIX_C_SOURCE=200809L _DEFAULT_SOURCE)
target_link_libraries(bench_pathtrace PRIVATE cg_static m)
add_dependencies(bench_pathtrace cg)
