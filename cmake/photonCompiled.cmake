# photon_add_compiled_units(NAME DSL_NAME [DEFINITIONS def...]): the optional compiled units
# that keep header-only use fast to build.
#   NAME:     a static library instantiating render() and its passes for DefaultScene<float> and
#             <double> (src/render_instantiations.cpp); linking it defines PHOTON_SEPARATE_COMPILATION,
#             so those functions are `extern template` in the linking program.
#   DSL_NAME: a static library with the scene-language reader and build<float|double>
#             (dsl/src/*.cpp); linking it defines PHOTON_DSL_SEPARATE_COMPILATION too.
# DEFINITIONS are compiled into both and passed on to their users (the tests add
# PHOTON_ENABLE_ASSERTS=1, so the compiled code checks what the tests' own code checks).
function(photon_add_compiled_units name dsl_name)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "DEFINITIONS")
  add_library(${name} STATIC ${PROJECT_SOURCE_DIR}/src/render_instantiations.cpp)
  target_link_libraries(${name} PUBLIC photon::photon PRIVATE photon_warnings)
  target_compile_definitions(${name} PUBLIC PHOTON_SEPARATE_COMPILATION=1 ${arg_DEFINITIONS})

  add_library(${dsl_name} STATIC ${PROJECT_SOURCE_DIR}/dsl/src/parser.cpp ${PROJECT_SOURCE_DIR}/dsl/src/build.cpp)
  target_link_libraries(${dsl_name} PUBLIC photon::dsl ${name} PRIVATE photon_warnings)
  if(TARGET photon::obj)  # build() reads mesh { obj "file" }: its users must agree on PHOTON_HAS_OBJ
    target_link_libraries(${dsl_name} PUBLIC photon::obj)
  endif()
  target_compile_definitions(${dsl_name} PUBLIC PHOTON_DSL_SEPARATE_COMPILATION=1)
endfunction()
