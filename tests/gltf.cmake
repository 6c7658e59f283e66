# The helper of tests/test_gltf_validator.sh: a mesh file and the .glb cg
# wrote from it, read back equal.
add_executable(gltf_compare ${CMAKE_CURRENT_LIST_DIR}/gltf_compare.c)
target_compile_options(gltf_compare PRIVATE ${CG_WARNINGS})
target_link_libraries(gltf_compare PRIVATE cg_static m)
