# The optional compiled units that keep header-only use quick to build (see docs/library.md,
# "Linking", and bench/README.md). EXCLUDE_FROM_ALL: built only for the programs that link them.
#
# photon_add_compiled_render(NAME [DEFINITIONS def...]): a static library instantiating render()
#   and its passes for DefaultScene<float> and <double> (src/render_instantiations.cpp), and the
#   image files' functions (src/image_io.cpp); linking it defines PHOTON_SEPARATE_COMPILATION, so
#   those functions are `extern template` or declared only in the program.
# photon_add_compiled_dsl(NAME RENDER_NAME): a static library with the scene-language reader and
#   build<float|double> (dsl/src/*.cpp) on top of RENDER_NAME; linking it defines
#   PHOTON_DSL_SEPARATE_COMPILATION too.
# DEFINITIONS are compiled in and passed on to the users (the tests add PHOTON_ENABLE_ASSERTS=1, so
# the compiled code checks what the tests' own code checks); the DSL unit takes its render unit's.
function(photon_add_compiled_render name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "DEFINITIONS")
  add_library(${name} STATIC EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/src/render_instantiations.cpp
                                              ${PROJECT_SOURCE_DIR}/src/image_io.cpp)
  target_link_libraries(${name} PUBLIC photon::photon PRIVATE photon_warnings)
  target_compile_definitions(${name} PUBLIC PHOTON_SEPARATE_COMPILATION=1 ${arg_DEFINITIONS})
endfunction()

function(photon_add_compiled_dsl name render_name)
  add_library(${name} STATIC EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/dsl/src/parser.cpp
                                              ${PROJECT_SOURCE_DIR}/dsl/src/build.cpp)
  target_link_libraries(${name} PUBLIC photon::dsl ${render_name} PRIVATE photon_warnings)
  if(TARGET photon::obj)  # build() reads mesh { obj "file" }: its users must agree on PHOTON_HAS_OBJ
    target_link_libraries(${name} PUBLIC photon::obj)
  endif()
  if(TARGET photon::fonts)  # build() reads text { ttf "file" }: its users must agree on PHOTON_HAS_FREETYPE
    target_link_libraries(${name} PUBLIC photon::fonts)
  endif()
  target_compile_definitions(${name} PUBLIC PHOTON_DSL_SEPARATE_COMPILATION=1)
endfunction()
