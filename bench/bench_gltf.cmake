# bench_gltf: glTF load time and peak memory against assimp (libassimp-dev).
add_executable(bench_gltf ${CMAKE_CURRENT_SOURCE_DIR}/bench_gltf.c)
target_compile_options(bench_gltf PRIVATE ${CG_WARNINGS})
target_link_libraries(bench_gltf PRIVATE cg_static)
pkg_check_modules(BENCH_ASSIMP IMPORTED_TARGET assimp)
cg_bench_peer(bench_gltf
              WHEN BENCH_ASSIMP_FOUND
              DEFINE CG_HAVE_ASSIMP
              LINK PkgConfig::BENCH_ASSIMP
              MESSAGE "bench_gltf: assimp not found (libassimp-dev); rows without a peer")
# The `cg mesh info FILE` rows run the build's cg tool.
target_compile_definitions(bench_gltf PRIVATE CG_TOOL="$<TARGET_FILE:cg>")
add_dependencies(bench_gltf cg)
