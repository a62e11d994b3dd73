# One interface target carrying our warning flags; applied to our targets only.
add_library(rt_warnings INTERFACE)
target_compile_options(rt_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast)
if(RT_WERROR)
  target_compile_options(rt_warnings INTERFACE -Werror)
endif()
if(RT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
