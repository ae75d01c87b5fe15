# sfx_embed_programs(<target> <manifest> <namespace>): every program of a shader_src/ manifest,
# compiled by sfxc at build time and embedded in the static library <target>, whose header
# <target>.hpp declares sfx::<namespace>::find/all. The runtime embeds programs.txt
# (sfx_shaders); the tests (programs_test.txt) and the tools' scenes (programs_scenes.txt) embed
# their own programs in their own libraries, so the runtime carries no test or tool code.
function(sfx_embed_programs target manifest cpp_namespace)
  set(SFX_SHADER_DIR ${PROJECT_SOURCE_DIR}/shader_src)
  file(GLOB inputs CONFIGURE_DEPENDS
    ${SFX_SHADER_DIR}/*.vert ${SFX_SHADER_DIR}/*.frag ${SFX_SHADER_DIR}/*.comp ${SFX_SHADER_DIR}/include/*.h)
  set(gen_dir ${PROJECT_BINARY_DIR}/generated/${target})
  if(SFX_SFXC_EXECUTABLE)
    set(sfxc_command ${SFX_SFXC_EXECUTABLE})
    set(sfxc_depends ${SFX_SFXC_EXECUTABLE})
  else()
    set(sfxc_command $<TARGET_FILE:sfxc>)
    set(sfxc_depends sfxc)
  endif()
  add_custom_command(
    OUTPUT ${gen_dir}/${target}.hpp ${gen_dir}/${target}.cpp
    COMMAND ${CMAKE_COMMAND} -E make_directory ${gen_dir}
    COMMAND ${sfxc_command} --manifest ${SFX_SHADER_DIR}/${manifest} -I ${SFX_SHADER_DIR}/include --namespace ${cpp_namespace}
            --out-header ${gen_dir}/${target}.hpp --out-source ${gen_dir}/${target}.cpp
    DEPENDS ${sfxc_depends} ${inputs} ${SFX_SHADER_DIR}/${manifest}
    COMMENT "sfxc: compiling shader_src/${manifest} to SPIR-V, ESSL 300/310, GLSL 330/450"
    VERBATIM)
  add_library(${target} STATIC ${gen_dir}/${target}.cpp)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${gen_dir}>)
  target_link_libraries(${target} PUBLIC sfx_core)
endfunction()
