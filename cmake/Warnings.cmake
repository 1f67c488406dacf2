# Compiler warnings for every wrc target: on, and treated as errors so that they stay clean.
function(wrc_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Werror)
endfunction()
