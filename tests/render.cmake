# The rendering pipeline against an independent renderer: Mesa's software
# OpenGL through OSMesa (Debian libosmesa6-dev).  Skipped when it is absent.
pkg_check_modules(OSMESA IMPORTED_TARGET osmesa)
if(OSMESA_FOUND)
  add_executable(test_render_osmesa ${CMAKE_CURRENT_SOURCE_DIR}/osmesa_render.c)
  target_compile_options(test_render_osmesa PRIVATE ${CG_WARNINGS})
  target_compile_definitions(test_render_osmesa PRIVATE CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_link_libraries(test_render_osmesa PRIVATE cg_static PkgConfig::OSMESA)
  add_test(NAME test_render_osmesa COMMAND test_render_osmesa
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # Mesa's own allocations kept to the end of the process are not cg's.
  set_tests_properties(test_render_osmesa PROPERTIES ENVIRONMENT
                       "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/osmesa.lsan")
  # The textured rasterizer against OSMesa's texturing.
  add_executable(test_render_osmesa_textured ${CMAKE_CURRENT_SOURCE_DIR}/osmesa_textured.c)
  target_compile_options(test_render_osmesa_textured PRIVATE ${CG_WARNINGS})
  target_link_libraries(test_render_osmesa_textured PRIVATE cg_static PkgConfig::OSMESA m)
  add_test(NAME test_render_osmesa_textured COMMAND test_render_osmesa_textured
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(test_render_osmesa_textured PROPERTIES ENVIRONMENT
                       "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/osmesa.lsan")
else()
  cg_add_missing_peer_test(test_render_osmesa "OSMesa" libosmesa6-dev)
  cg_add_missing_peer_test(test_render_osmesa_textured "OSMesa" libosmesa6-dev)
endif()
