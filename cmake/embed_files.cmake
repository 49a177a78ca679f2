# Embeds files in the binary at build time: the files in the tree stay the source of truth and nothing
# reads them from the working directory at run time.
#   shadelab_embed(<out-var> <name> <glob> <header> <namespace::function>)
# generates ${SHADELAB_GENERATED}/<name>.cpp defining
#   std::optional<std::string_view> <namespace::function>(std::string_view fileName)
# as declared in <header>, and sets <out-var> to that file for add_library.
function(shadelab_embed out_var name pattern header function)
  file(GLOB files CONFIGURE_DEPENDS ${pattern})
  set(output ${SHADELAB_GENERATED}/${name}.cpp)
  string(REGEX REPLACE "::[^:]*$" "" namespace ${function})
  string(REGEX REPLACE "^.*::" "" function_name ${function})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} "-DINPUTS=${files}" -DHEADER=${header}
            -DNAMESPACE=${namespace} -DFUNCTION=${function_name} -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/embed_files_run.cmake
    DEPENDS ${files} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/embed_files_run.cmake
    COMMENT "Embedding ${name}"
    VERBATIM)
  set(${out_var} ${output} PARENT_SCOPE)
endfunction()
