# oss_embed_shaders(<out.cpp> <namespace-free function prefix> <glsl files...>)
#
# Turns each .glsl file into a C++ raw string literal at build time, so the library
# ships its shaders without needing them on disk. At run time a file of the same name
# found through OSG_FILE_PATH (osgShadowSilhouette/shaders/<name>) replaces the
# embedded text, so shaders can be edited without rebuilding.
set(_OSS_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedShadersScript.cmake)

function(oss_embed_shaders OUT)
  set(_files ${ARGN})
  add_custom_command(
    OUTPUT ${OUT}
    COMMAND ${CMAKE_COMMAND} -DOUT=${OUT} "-DFILES=${_files}" -P ${_OSS_EMBED_SCRIPT}
    DEPENDS ${_files} ${_OSS_EMBED_SCRIPT}
    COMMENT "Embedding GLSL shaders"
    VERBATIM)
endfunction()
