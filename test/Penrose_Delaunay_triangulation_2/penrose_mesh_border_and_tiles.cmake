# Runs penrose_mesh (PENROSE_MESH) on the bundled inputs in DATA and checks
# its meshes with mesh_check (MESH_CHECK), in WORK: the triangles at the
# border are well shaped, and --tiles gives seamless tiles.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run_mesh)
  execute_process(COMMAND ${PENROSE_MESH} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "penrose_mesh ${ARGN}: status ${rc}: ${err}")
  endif()
endfunction()

# No triangle with a vertex on the border has an angle under 15 degrees: a
# terrain (greedy insertion), an image, the ramp (no point on its left side,
# where the density is 0), with a vertex budget or an error bound.
set(cases
  "--terrain|${DATA}/terrain.png|--points 2000" "--terrain|${DATA}/terrain.png|--points 20000"
  "--terrain|${DATA}/terrain.png|--max-error 300" "--terrain|${DATA}/terrain.png|--points 20000 --base-fraction 1"
  "--density|image:${DATA}/test_image.png|--gradient --points 5120" "--density|image:${DATA}/test_image.png|--max-error 0.05"
  "--density|ramp|--boundary --points 1000" "--density|ramp|--boundary --points 20000")
foreach(c ${cases})
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 input)
  list(GET c 1 value)
  list(GET c 2 options)
  separate_arguments(options)
  run_mesh(${input} ${value} ${options} --out-mesh ${WORK}/border.off)
  execute_process(COMMAND ${MESH_CHECK} border-angle ${WORK}/border.off OUTPUT_VARIABLE angle RESULT_VARIABLE rc)
  string(STRIP "${angle}" angle)
  if(NOT rc EQUAL 0 OR angle LESS 15)
    string(REPLACE ";" " " options "${options}")
    message(FATAL_ERROR "${input} ${value} ${options}: a triangle at the border has an angle of ${angle} degrees")
  endif()
endforeach()

# --tiles 3 on the bundled terrain: each tile covers its rectangle, the
# vertices on a side shared by two tiles are the same in both, bit for bit,
# and a tile computed alone (--tile I J) is the same file, byte for byte.
# The same with --max-error, which adds border points where the heights
# along a side need them.
file(MAKE_DIRECTORY ${WORK}/tiles)
foreach(name points error)
  set(bound --points 20000)
  if(name STREQUAL error)
    set(bound --max-error 300)
  endif()
  run_mesh(--terrain ${DATA}/terrain.png ${bound} --tiles 3 --out-mesh ${WORK}/tiles/${name}.off)
  execute_process(COMMAND ${MESH_CHECK} tiles 3 ${WORK}/tiles/${name} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--tiles 3 ${bound}: ${out}")
  endif()
endforeach()
foreach(tile "0 0" "1 1" "2 1")
  separate_arguments(tile)
  list(JOIN tile "_" name)
  file(MAKE_DIRECTORY ${WORK}/alone)
  run_mesh(--terrain ${DATA}/terrain.png --points 20000 --tiles 3 --tile ${tile} --out-mesh ${WORK}/alone/points.off)
  file(SHA256 ${WORK}/tiles/points_${name}.off together)
  file(SHA256 ${WORK}/alone/points_${name}.off alone)
  file(GLOB written ${WORK}/alone/*)
  list(LENGTH written count)
  if(NOT together STREQUAL alone OR NOT count EQUAL 1)
    message(FATAL_ERROR "--tile ${tile}: not the tile of --tiles 3, or ${count} files written")
  endif()
  file(REMOVE_RECURSE ${WORK}/alone)
endforeach()
