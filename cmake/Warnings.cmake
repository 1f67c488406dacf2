# SPDX-License-Identifier: Apache-2.0
# Compiler warnings for every wrc target: on, and treated as errors so that they stay clean.
# WRC_WERROR (default ON, as CI builds): warnings are errors; -DWRC_WERROR=OFF for a compiler
# that warns where this one does not.
option(WRC_WERROR "treat compiler warnings as errors" ON)
function(wrc_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  if(WRC_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
