# The ray tracer against Embree 3 (libembree-dev): nearest-hit triangles of
# random rays on the same meshes must agree.  Skipped when Embree is absent.
find_package(embree 3 QUIET)
if(embree_FOUND AND TARGET embree)
  add_executable(trace_embree ${CMAKE_CURRENT_LIST_DIR}/trace_embree.c)
  target_compile_options(trace_embree PRIVATE ${CG_WARNINGS})
  target_link_libraries(trace_embree PRIVATE cg_static embree)
  add_test(NAME test_trace_embree COMMAND trace_embree)
else()
  cg_add_missing_peer_test(test_trace_embree "Embree 3" libembree-dev)
endif()
