# Warning policy for the project's own targets (never for third-party code).
function(k528_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()
