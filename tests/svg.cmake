# The helper of tests/test_svg_peers.sh: compares cg's and rsvg-convert's
# renderings of the Papirus sample with resvg's.
add_executable(svg_compare ${CMAKE_CURRENT_LIST_DIR}/svg_compare.c)
target_compile_options(svg_compare PRIVATE ${CG_WARNINGS})
target_link_libraries(svg_compare PRIVATE cg_static m)
