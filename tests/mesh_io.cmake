# Mesh files: the readers over every model of Debian's assimp-testmodels
# package, and (with -DCG_FUZZ=ON, clang only) a libFuzzer target per reader
# that CTest runs briefly from a small seed corpus.

# ---- assimp-testmodels ------------------------------------------------------
find_path(CG_ASSIMP_MODELS NAMES OBJ/box.obj PLY/cube.ply
  PATHS /usr/share/assimp/models /usr/share/assimp-testmodels /usr/share/assimp-testmodels/models
  NO_DEFAULT_PATH)
if(NOT CG_ASSIMP_MODELS)
  message(STATUS "assimp-testmodels not found: test_mesh_io_models will be skipped "
                 "(apt-get install assimp-testmodels)")
  set(CG_ASSIMP_MODELS "${CMAKE_CURRENT_BINARY_DIR}/no-assimp-testmodels")
endif()
add_executable(test_mesh_io_models ${CMAKE_CURRENT_SOURCE_DIR}/mesh_io_models.c)
target_compile_options(test_mesh_io_models PRIVATE ${CG_WARNINGS})
target_link_libraries(test_mesh_io_models PRIVATE cg_static)
add_test(NAME test_mesh_io_models COMMAND test_mesh_io_models ${CG_ASSIMP_MODELS})
set_tests_properties(test_mesh_io_models PROPERTIES SKIP_RETURN_CODE 77)

# ---- fuzz targets -------------------------------------------------------------
if(CG_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CG_FUZZ needs clang (libFuzzer): configure with -DCMAKE_C_COMPILER=clang")
  endif()
  # the library again, instrumented for coverage-guided fuzzing
  add_library(cg_fuzz_objects STATIC ${CG_SOURCES})
  target_include_directories(cg_fuzz_objects PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_compile_options(cg_fuzz_objects PRIVATE -g -O1 -fsanitize=fuzzer-no-link,address,undefined)
  target_link_libraries(cg_fuzz_objects PUBLIC PkgConfig::PNG PkgConfig::ZLIB Threads::Threads m)
  set(CG_FUZZ_TIME 10 CACHE STRING "Seconds each fuzz target runs under ctest")
  foreach(format obj ply off stl auto)
    string(TOUPPER ${format} upper)
    set(target fuzz_mesh_${format})
    add_executable(${target} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_mesh.c)
    target_compile_definitions(${target} PRIVATE FUZZ_FORMAT=CG_MESH_FORMAT_${upper}
                               FUZZ_NAME="fuzz.${format}")
    target_compile_options(${target} PRIVATE -g -O1 -fsanitize=fuzzer,address,undefined ${CG_WARNINGS})
    target_link_options(${target} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_libraries(${target} PRIVATE cg_fuzz_objects)
    # new inputs go to a corpus in the build tree; the seeds stay untouched
    set(corpus ${CMAKE_CURRENT_BINARY_DIR}/fuzz-corpus/${format})
    file(MAKE_DIRECTORY ${corpus})
    set(dict)
    if(format STREQUAL "obj" OR format STREQUAL "ply")
      set(dict -dict=${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${format}.dict)
    endif()
    add_test(NAME ${target}
             COMMAND ${target} -max_total_time=${CG_FUZZ_TIME} -rss_limit_mb=1024 -timeout=10
                     -max_len=65536 ${dict} ${corpus} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/seeds/${format})
    set_tests_properties(${target} PROPERTIES LABELS fuzz)
  endforeach()
endif()
