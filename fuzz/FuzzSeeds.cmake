# The seed corpora, written at configure time into ${RT_FUZZ_SEEDS}/<target>/ from the shipped
# scenes (scenes/, tests/data/scene/) and the few seeds checked in under fuzz/seeds/<target>/.
# A .scn whose first line is "flags: -M" (tests/data/scene/bad) keeps its switches: as the
# "# fuzz-switches:" line of the scn target, and on the marker line of the scene_render target.

set(_root ${PROJECT_SOURCE_DIR})
file(GLOB _shipped_scn CONFIGURE_DEPENDS ${_root}/scenes/*.scn ${_root}/tests/data/scene/*/*.scn)
file(GLOB _checked_in CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/seeds/*/*)

# Copies FILES into the seed folder of TARGET, each named after its folder and itself.
function(rt_fuzz_seed_files target)
  foreach(path ${ARGN})
    get_filename_component(dir ${path} DIRECTORY)
    get_filename_component(dir ${dir} NAME)
    get_filename_component(name ${path} NAME)
    configure_file(${path} ${RT_FUZZ_SEEDS}/${target}/${dir}-${name} COPYONLY)
  endforeach()
endfunction()

# The switches a .scn's "flags:" first line gives, in `out`.
function(rt_fuzz_scn_switches text out)
  string(REGEX MATCH "^flags:([^\n]*)" line "${text}")
  set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

# The whole scene folder of one .scn as one input (scene_folder.h): the .scn, then every file of
# its folder (and models/) that it names as a word, up to 16 KB each. With_textures adds -V.
function(rt_fuzz_scene_container scn with_textures)
  get_filename_component(dir ${scn} DIRECTORY)
  get_filename_component(stem ${scn} NAME_WE)
  get_filename_component(dirname ${dir} NAME)
  file(READ ${scn} text)
  rt_fuzz_scn_switches("${text}" switches)
  if(with_textures)
    set(switches "${switches} -V")
    set(stem "${stem}-V")
  endif()
  set(container "=== fuzz.scn${switches}\n${text}")
  file(GLOB candidates LIST_DIRECTORIES false ${dir}/* ${dir}/models/*)
  foreach(file ${candidates})
    file(RELATIVE_PATH name ${dir} ${file})
    file(SIZE ${file} size)
    string(REGEX REPLACE "([.+])" "\\\\\\1" pattern "${name}")
    if(size LESS_EQUAL 16384 AND NOT name MATCHES "\\.(scn|png|md|expected)$" AND
       text MATCHES "[ \t@]${pattern}([ \t\r\n]|$)")
      file(READ ${file} bytes)
      string(APPEND container "=== ${name}\n${bytes}")
    endif()
  endforeach()
  file(WRITE ${RT_FUZZ_SEEDS}/scene_render/${dirname}-${stem} "${container}")
endfunction()

file(REMOVE_RECURSE ${RT_FUZZ_SEEDS})
foreach(scn ${_shipped_scn})
  get_filename_component(dir ${scn} DIRECTORY)
  get_filename_component(dirname ${dir} NAME)
  get_filename_component(stem ${scn} NAME_WE)
  file(READ ${scn} text)
  rt_fuzz_scn_switches("${text}" switches)
  file(WRITE ${RT_FUZZ_SEEDS}/scn/${dirname}-${stem} "# fuzz-switches:${switches}\n${text}")
  rt_fuzz_scene_container(${scn} FALSE)
  if(text MATCHES "\\.dat")
    file(WRITE ${RT_FUZZ_SEEDS}/scn/${dirname}-${stem}-V "# fuzz-switches:${switches} -V\n${text}")
    rt_fuzz_scene_container(${scn} TRUE)
  endif()
endforeach()

file(GLOB _attributes ${_root}/scenes/Attributes ${_root}/scenes/*-attributes
     ${_root}/tests/data/scene/*/Attributes ${_root}/tests/data/scene/*/*.attributes)
rt_fuzz_seed_files(attributes ${_attributes})
file(GLOB _polygon_files ${_root}/scenes/cube ${_root}/scenes/checker8 ${_root}/scenes/square
     ${_root}/scenes/sphere ${_root}/tests/data/scene/manual/cube
     ${_root}/tests/data/scene/*/*.surf ${_root}/tests/data/scene/bad/tri)
rt_fuzz_seed_files(polygon_file ${_polygon_files})
file(GLOB _phigs ${_root}/tests/data/scene/phigscube ${_root}/tests/data/scene/*/*.phigs)
rt_fuzz_seed_files(phigs ${_phigs})
file(GLOB _prinz ${_root}/tests/data/scene/manual/prinzcube ${_root}/tests/data/scene/*/*.prinz)
rt_fuzz_seed_files(prinz ${_prinz})
file(GLOB _shapes ${_root}/tests/data/scene/*/*.shapes)
rt_fuzz_seed_files(shape_file ${_shapes})
file(GLOB _dat ${_root}/scenes/*.dat)
rt_fuzz_seed_files(grid_file ${_dat})
rt_fuzz_seed_files(texture_map ${_dat})
rt_fuzz_seed_files(model ${_root}/scenes/models/cornell_box.obj)
foreach(path ${_checked_in})
  get_filename_component(dir ${path} DIRECTORY)
  get_filename_component(target ${dir} NAME)
  rt_fuzz_seed_files(${target} ${path})
endforeach()
