# zome_target_warnings(target): the project's warning set; -Werror when ZOME_STRICT is on.
function(zome_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wpedantic -Wnon-virtual-dtor)
  if(ZOME_STRICT)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
