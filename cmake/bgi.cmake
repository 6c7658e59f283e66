# libcg-bgi: the BGI graphics calls of course labs (include/cg/bgi.h, with
# graphics.h, conio.h and dos.h in include/cg-bgi/), drawn by libcg, shown
# through SDL2 when there is a display.  A library of its own, so that libcg
# needs no SDL2 and defines no BGI name; its own sources are src/bgi/ (left
# out of libcg's glob) and the 5 x 7 font of the cg tool.
file(GLOB CG_BGI_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/bgi/*.c)
add_library(cg_bgi SHARED ${CG_BGI_SOURCES} ${PROJECT_SOURCE_DIR}/tools/cg/draw/font5x7.c)
target_include_directories(cg_bgi PRIVATE ${PROJECT_SOURCE_DIR}/tools/cg/draw)
target_compile_options(cg_bgi PRIVATE ${CG_WARNINGS})
target_link_libraries(cg_bgi PRIVATE cg_shared)
pkg_check_modules(CG_BGI_SDL2 IMPORTED_TARGET sdl2)
if(CG_BGI_SDL2_FOUND)
  target_compile_definitions(cg_bgi PRIVATE CG_HAVE_SDL2)
  target_link_libraries(cg_bgi PRIVATE PkgConfig::CG_BGI_SDL2)
else()
  message(STATUS "SDL2 not found: BGI programs draw into memory only")
endif()
# Only the cg_bgi_ functions are exported; libcg.so is found beside it.
set(CG_BGI_VERSION_SCRIPT ${PROJECT_BINARY_DIR}/libcg-bgi.map)
file(WRITE ${CG_BGI_VERSION_SCRIPT} "{ global: cg_bgi_*; local: *; };\n")
target_link_options(cg_bgi PRIVATE -Wl,--version-script=${CG_BGI_VERSION_SCRIPT})
set_target_properties(cg_bgi PROPERTIES OUTPUT_NAME cg-bgi VERSION ${PROJECT_VERSION}
                      SOVERSION ${PROJECT_VERSION_MAJOR} INSTALL_RPATH "$ORIGIN"
                      LINK_DEPENDS ${CG_BGI_VERSION_SCRIPT})
install(TARGETS cg_bgi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
configure_file(${PROJECT_SOURCE_DIR}/cmake/cg-bgi.pc.in ${PROJECT_BINARY_DIR}/cg-bgi.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/cg-bgi.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
