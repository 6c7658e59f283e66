# The helper of tests/test_draw_text.sh: the library calls `cg draw`'s text
# commands must match (a paragraph filled, a run measured, greedy breaks).
add_executable(text_reference ${CMAKE_CURRENT_LIST_DIR}/text_reference.c)
target_compile_options(text_reference PRIVATE ${CG_WARNINGS})
target_link_libraries(text_reference PRIVATE cg_static m)
