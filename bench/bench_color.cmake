# bench_color: cg's colour conversions against OpenCV's cvtColor (C++).
find_package(OpenCV QUIET COMPONENTS core imgproc)
if(OpenCV_FOUND)
  add_executable(bench_color ${CMAKE_CURRENT_SOURCE_DIR}/bench_color.c
                             ${CMAKE_CURRENT_SOURCE_DIR}/bench_color_opencv.cpp)
  target_compile_definitions(bench_color PRIVATE CG_BENCH_OPENCV=1)
  target_include_directories(bench_color PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(bench_color PRIVATE cg_static ${OpenCV_LIBS})
else()
  message(STATUS "bench_color: OpenCV not found, building without the peer")
  add_executable(bench_color ${CMAKE_CURRENT_SOURCE_DIR}/bench_color.c)
  target_link_libraries(bench_color PRIVATE cg_static)
endif()
target_compile_options(bench_color PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
