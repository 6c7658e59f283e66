# Mesh files: the readers over every model of Debian's assimp-testmodels
# package (real and deliberately broken files).

# ---- assimp-testmodels ------------------------------------------------------
set(CG_ASSIMP_MODEL_DIRS /usr/share/assimp/models /usr/share/assimp-testmodels
                         /usr/share/assimp-testmodels/models)
find_path(CG_ASSIMP_MODELS NAMES OBJ/box.obj PLY/cube.ply PATHS ${CG_ASSIMP_MODEL_DIRS}
  NO_DEFAULT_PATH)
if(NOT CG_ASSIMP_MODELS)
  # The test looks in each place when it runs, and says it is skipped when the
  # package is in none of them.
  message(STATUS "assimp-testmodels not found yet: test_mesh_io_models looks again when it "
                 "runs (apt-get install assimp-testmodels)")
  set(CG_ASSIMP_MODELS ${CG_ASSIMP_MODEL_DIRS})
endif()
add_executable(test_mesh_io_models ${CMAKE_CURRENT_SOURCE_DIR}/mesh_io_models.c)
target_compile_options(test_mesh_io_models PRIVATE ${CG_WARNINGS})
target_link_libraries(test_mesh_io_models PRIVATE cg_static)
add_test(NAME test_mesh_io_models COMMAND test_mesh_io_models ${CG_ASSIMP_MODELS})
set_tests_properties(test_mesh_io_models PROPERTIES SKIP_RETURN_CODE 77)

# The fuzz targets (tests/fuzz/fuzz_mesh_*.c) are built and run by the generic
# rule in tests/CMakeLists.txt when CG_FUZZ is on.

# ---- glTF against assimp ------------------------------------------------------
# test_mesh_gltf_assimp loads every glTF 2.0 model of assimp-testmodels with
# cg and with assimp (libassimp-dev) and compares the triangles.
pkg_check_modules(ASSIMP IMPORTED_TARGET assimp)
if(ASSIMP_FOUND)
  add_executable(test_mesh_gltf_assimp ${CMAKE_CURRENT_SOURCE_DIR}/mesh_gltf_assimp.c)
  target_compile_options(test_mesh_gltf_assimp PRIVATE ${CG_WARNINGS})
  target_link_libraries(test_mesh_gltf_assimp PRIVATE cg_static PkgConfig::ASSIMP)
  add_test(NAME test_mesh_gltf_assimp COMMAND test_mesh_gltf_assimp)
  set_tests_properties(test_mesh_gltf_assimp PROPERTIES SKIP_RETURN_CODE 77)
else()
  cg_add_missing_peer_test(test_mesh_gltf_assimp "assimp" libassimp-dev)
endif()
