# bench_draw_script: scripts run by the cg tool (`cg draw --repeat`) against
# the library calls they make and against OpenCV (libopencv-dev), AGG
# (libagg-dev) and Cairo (libcairo2-dev) drawing the same shapes; a peer that
# is not installed is skipped with a row saying so.
pkg_check_modules(DRAW_SCRIPT_CAIRO QUIET IMPORTED_TARGET cairo)
pkg_check_modules(DRAW_SCRIPT_AGG QUIET IMPORTED_TARGET libagg)
find_package(OpenCV QUIET COMPONENTS core imgproc)
add_executable(bench_draw_script ${CMAKE_CURRENT_SOURCE_DIR}/bench_draw_script.c
                                 ${CMAKE_CURRENT_SOURCE_DIR}/bench_draw_script_peers.cpp)
target_compile_options(bench_draw_script PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_compile_definitions(bench_draw_script PRIVATE CG_TOOL="$<TARGET_FILE:cg>"
                                                     _POSIX_C_SOURCE=200809L _DEFAULT_SOURCE)
target_link_libraries(bench_draw_script PRIVATE cg_static m)
add_dependencies(bench_draw_script cg)
if(DRAW_SCRIPT_CAIRO_FOUND)
  target_compile_definitions(bench_draw_script PRIVATE CG_BENCH_HAVE_CAIRO)
  target_link_libraries(bench_draw_script PRIVATE PkgConfig::DRAW_SCRIPT_CAIRO)
else()
  message(STATUS "bench_draw_script: Cairo not found, its rows are skipped")
endif()
if(DRAW_SCRIPT_AGG_FOUND)
  target_compile_definitions(bench_draw_script PRIVATE CG_BENCH_HAVE_AGG)
  target_link_libraries(bench_draw_script PRIVATE PkgConfig::DRAW_SCRIPT_AGG)
else()
  message(STATUS "bench_draw_script: AGG (libagg-dev) not found, its rows are skipped")
endif()
if(OpenCV_FOUND)
  target_compile_definitions(bench_draw_script PRIVATE CG_BENCH_HAVE_OPENCV)
  target_include_directories(bench_draw_script PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(bench_draw_script PRIVATE opencv_core opencv_imgproc)
else()
  message(STATUS "bench_draw_script: OpenCV not found, its rows are skipped")
endif()
