# bench_mesh_io: OBJ and PLY read speed against tinyobjloader (OBJ) and
# OpenMesh (OBJ, PLY).  Either peer may be missing: its rows then say so.
add_executable(bench_mesh_io ${CMAKE_CURRENT_SOURCE_DIR}/bench_mesh_io.c
                             ${CMAKE_CURRENT_SOURCE_DIR}/bench_mesh_io_peers.cpp)
target_compile_options(bench_mesh_io PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_compile_definitions(bench_mesh_io PRIVATE CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(bench_mesh_io PRIVATE cg_static)

pkg_check_modules(TINYOBJ IMPORTED_TARGET tinyobjloader)
cg_bench_peer(bench_mesh_io
              WHEN TINYOBJ_FOUND
              DEFINE CG_HAVE_TINYOBJ
              LINK PkgConfig::TINYOBJ
              MESSAGE "bench_mesh_io: tinyobjloader not found (libtinyobjloader-dev); OBJ rows without a peer")

find_path(OPENMESH_INCLUDE OpenMesh/Core/IO/MeshIO.hh)
find_library(OPENMESH_CORE OpenMeshCore)
cg_bench_peer(bench_mesh_io
              WHEN OPENMESH_INCLUDE AND OPENMESH_CORE
              DEFINE CG_HAVE_OPENMESH _USE_MATH_DEFINES
              INCLUDE ${OPENMESH_INCLUDE}
              LINK ${OPENMESH_CORE}
              MESSAGE "bench_mesh_io: OpenMesh not found (libopenmesh-dev); PLY rows without a peer")
