# Runs penrose_mesh (PENROSE_MESH) on the bundled inputs in DATA and on bad
# files made in WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run_mesh)
  execute_process(COMMAND ${PENROSE_MESH} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  set(rc "${rc}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(json_number json key out)
  string(REGEX MATCH "\"${key}\": ([-0-9.e+]+)" m "${json}")
  if(NOT m)
    message(FATAL_ERROR "no \"${key}\" in ${json}")
  endif()
  set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

# The bundled terrain and image: every output, and the mesh beats the grid.
run_mesh(--terrain ${DATA}/terrain.png --points 20000 --boundary --out-mesh ${WORK}/terrain.ply
         --out-points ${WORK}/terrain.xyz --png ${WORK}/terrain.png --svg ${WORK}/terrain.svg
         --stats-json ${WORK}/terrain.json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "terrain run failed (${rc}): ${err}")
endif()
file(READ ${WORK}/terrain.json json)
foreach(key points sample_seconds triangulate_seconds vertices faces flips fallbacks)
  json_number("${json}" ${key} value)
endforeach()
json_number("${json}" rms_error rms)
json_number("${json}" grid_rms_error grid_rms)
json_number("${json}" max_error max)
json_number("${json}" grid_max_error grid_max)
if(NOT rms LESS grid_rms)
  message(FATAL_ERROR "terrain: the mesh's RMS error ${rms} is not below the grid's ${grid_rms}")
endif()
foreach(f terrain.ply terrain.xyz terrain.png terrain.svg)
  file(SIZE ${WORK}/${f} size)
  if(size EQUAL 0)
    message(FATAL_ERROR "${f} is empty")
  endif()
endforeach()

run_mesh(--density image:${DATA}/test_image.png --gradient --points 5120 --boundary
         --reconstruct ${WORK}/image.png --out-mesh ${WORK}/image.obj --stats-json ${WORK}/image.json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "image run failed (${rc}): ${err}")
endif()
file(READ ${WORK}/image.json json)
json_number("${json}" psnr psnr)
json_number("${json}" grid_psnr grid_psnr)
if(NOT psnr GREATER grid_psnr)
  message(FATAL_ERROR "image: the mesh's PSNR ${psnr} is not above the grid's ${grid_psnr}")
endif()

# Bad files: exit status 1 and one line that names the file and the problem.
file(WRITE ${WORK}/empty.png "")
file(WRITE ${WORK}/text.png "not an image\n")
file(WRITE ${WORK}/truncated.pgm "P5\n64 64\n65535\nabc")
file(WRITE ${WORK}/huge.pgm "P5\n2000000 2000000\n255\nabc")
file(WRITE ${WORK}/short.asc "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n")
file(WRITE ${WORK}/huge.asc "ncols 900000000\nnrows 900000000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n")
set(cases
  "missing.png|cannot open" "empty.png|empty file" "text.png|cannot read as an image"
  "truncated.pgm|truncated" "huge.pgm|absurd dimensions" "short.asc|truncated" "huge.asc|absurd dimensions")
foreach(c ${cases})
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 name)
  list(GET c 1 why)
  foreach(option --terrain --density)
    if(option STREQUAL "--density")
      if(name MATCHES "asc$")
        continue()
      endif()
      run_mesh(--density image:${WORK}/${name})
    else()
      run_mesh(--terrain ${WORK}/${name})
    endif()
    string(STRIP "${err}" line)
    if(NOT rc EQUAL 1 OR NOT line MATCHES "^penrose_mesh: [^\n]*${name}: [^\n]*${why}[^\n]*$")
      message(FATAL_ERROR "${option} ${name}: expected status 1 and one line about '${why}', got ${rc}: ${err}")
    endif()
  endforeach()
endforeach()

# Bad outputs too.
run_mesh(--density ramp --points 100 --out-mesh ${WORK}/mesh.stl)
if(NOT rc EQUAL 1 OR NOT err MATCHES "mesh.stl: unknown mesh format")
  message(FATAL_ERROR "--out-mesh mesh.stl: got ${rc}: ${err}")
endif()

# A count beyond std::size_t is refused, not wrapped around (1e30 gave 0 points).
run_mesh(--density constant --points 1e30)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--points must be at most")
  message(FATAL_ERROR "--points 1e30: got ${rc}: ${err}")
endif()

# --gamma applies to the analytic densities too (it was ignored): the ramp
# squared puts an eighth of its points left of x = 0.5, against a quarter.
foreach(gamma 1 2)
  run_mesh(--density ramp --points 4000 --gamma ${gamma} --out-points ${WORK}/ramp${gamma}.xy)
  file(STRINGS ${WORK}/ramp${gamma}.xy left REGEX "^0\\.[0-4]")
  list(LENGTH left left_${gamma})
endforeach()
math(EXPR limit "${left_1} * 3 / 4")
if(NOT left_2 LESS limit OR left_1 LESS 800)
  message(FATAL_ERROR "--gamma 2: ${left_2} points left of 0.5, against ${left_1} with --gamma 1")
endif()
