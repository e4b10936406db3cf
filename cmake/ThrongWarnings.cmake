# throng_warnings(target): our code builds clean with -Wall -Wextra -Wpedantic -Werror.
function(throng_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()
