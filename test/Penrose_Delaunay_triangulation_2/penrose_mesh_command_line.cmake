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

# --reconstruct without a density option: a sample, then greedy insertion on
# the luminance, which beats the edges' importance sampling above.
run_mesh(--density image:${DATA}/test_image.png --points 5120 --reconstruct ${WORK}/image_greedy.png
         --stats-json ${WORK}/image_greedy.json)
file(READ ${WORK}/image_greedy.json json)
json_number("${json}" inserted_points inserted)
json_number("${json}" psnr greedy_psnr)
if(NOT rc EQUAL 0 OR NOT inserted GREATER 4000 OR NOT greedy_psnr GREATER psnr)
  message(FATAL_ERROR "image --reconstruct: status ${rc}, ${inserted} inserted, PSNR ${greedy_psnr} (--gradient ${psnr}): ${err}")
endif()

# With --fit-heights, the colours fitted: a higher PSNR.
run_mesh(--density image:${DATA}/test_image.png --points 5120 --reconstruct ${WORK}/image_fit.png --fit-heights
         --stats-json ${WORK}/image_fit.json)
file(READ ${WORK}/image_fit.json json)
json_number("${json}" psnr fit_psnr)
if(NOT rc EQUAL 0 OR NOT fit_psnr GREATER greedy_psnr)
  message(FATAL_ERROR "image --reconstruct --fit-heights: status ${rc}, PSNR ${fit_psnr} (without: ${greedy_psnr}): ${err}")
endif()

# Bad files: exit status 1 and one line that names the file and the problem.
file(WRITE ${WORK}/empty.png "")
file(WRITE ${WORK}/text.png "not an image\n")
file(WRITE ${WORK}/truncated.pgm "P5\n64 64\n65535\nabc")
file(WRITE ${WORK}/huge.pgm "P5\n2000000 2000000\n255\nabc")
file(WRITE ${WORK}/short.asc "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n")
file(WRITE ${WORK}/huge.asc "ncols 900000000\nnrows 900000000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n")
set(grid "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n")
file(WRITE ${WORK}/long.asc "${grid}cellsize 1\n1 2 3 4\n5 6\n")
file(WRITE ${WORK}/rows.asc "${grid}cellsize 1\n1 2 3\n4 5 6\n7 8 9\n")
file(WRITE ${WORK}/extent.asc "${grid}cellsize 1e308\n1 2 3\n4 5 6\n")
file(WRITE ${WORK}/steep.asc "${grid}cellsize 1e-300\n1 2 3\n4 5 1e300\n")
file(MAKE_DIRECTORY ${WORK}/directory.png)
set(cases
  "missing.png|cannot open" "empty.png|empty file" "text.png|cannot read as an image"
  "truncated.pgm|truncated" "huge.pgm|absurd dimensions" "short.asc|truncated" "huge.asc|absurd dimensions"
  "long.asc|line 6: more values than ncols" "rows.asc|line 8: more rows than nrows"
  "extent.asc|extent" "steep.asc|curvature of its heights overflows" "directory.png|is a directory")
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

# --max-pixels lowers the limit on the pixels that a header may claim.
run_mesh(--terrain ${DATA}/terrain.png --max-pixels 1000)
if(NOT rc EQUAL 1 OR NOT err MATCHES "terrain.png: absurd dimensions [^\n]*limit is 1000 pixels")
  message(FATAL_ERROR "--max-pixels 1000: got ${rc}: ${err}")
endif()

# Outputs that cannot be written (a full disk), however small.
foreach(output --out-points:xy --out-mesh:off --out-mesh:ply --out-mesh:obj --svg:svg --png:png --stats-json:json
        --reconstruct:png)
  string(REPLACE ":" ";" output "${output}")
  list(GET output 0 option)
  list(GET output 1 extension)
  file(CREATE_LINK /dev/full ${WORK}/full.${extension} SYMBOLIC)
  run_mesh(--density image:${DATA}/test_image.png --points 1 ${option} ${WORK}/full.${extension})
  if(NOT rc EQUAL 1 OR NOT err MATCHES "^penrose_mesh: [^\n]*full.${extension}: [^\n]*(write|encode)[^\n]*\n$")
    message(FATAL_ERROR "${option} /dev/full: expected status 1 and one line naming the file, got ${rc}: ${err}")
  endif()
endforeach()

# A mesh without faces has no PSNR (null, not inf); a file name with a quote,
# '<' and '&' stays a string in the JSON and a link in the SVG.
file(COPY_FILE ${DATA}/test_image.png "${WORK}/q\"<&.png")
run_mesh(--density "image:${WORK}/q\"<&.png" --points 1 --no-boundary --stats-json ${WORK}/names.json --svg ${WORK}/names.svg)
file(READ ${WORK}/names.json json)
string(JSON density ERROR_VARIABLE json_error GET "${json}" density)
string(JSON psnr_type ERROR_VARIABLE json_error TYPE "${json}" psnr)
if(NOT rc EQUAL 0 OR json_error OR NOT density STREQUAL "${WORK}/q\"<&.png" OR NOT psnr_type STREQUAL "NULL")
  message(FATAL_ERROR "names.json (${rc}, ${json_error}): density '${density}', psnr '${psnr_type}': ${json}")
endif()
file(READ ${WORK}/names.svg svg)
if(NOT svg MATCHES "xlink:href=\"q%22%3C%26.png\"")
  message(FATAL_ERROR "names.svg: the file name is not percent-encoded")
endif()

# A name with %, #, ?, a space, a control character, a byte that is not
# UTF-8 and an accent, its SVG in another folder: the link is relative to
# the SVG's folder and percent-encoded (XML 1.0 forbids control characters
# even escaped), the JSON valid UTF-8 (U+FFFD for the stray byte).
string(ASCII 1 control)
string(ASCII 255 latin1)
set(odd "a%#? ${control}${latin1}é.png")
file(MAKE_DIRECTORY ${WORK}/images ${WORK}/drawings)
file(COPY_FILE ${DATA}/test_image.png "${WORK}/images/${odd}")
run_mesh(--density "image:${WORK}/images/${odd}" --points 50 --svg ${WORK}/drawings/odd.svg --stats-json ${WORK}/odd.json)
file(READ ${WORK}/drawings/odd.svg svg)
file(READ ${WORK}/odd.json json HEX)
string(HEX "/images/a%#? " name_start)
if(NOT rc EQUAL 0 OR NOT svg MATCHES "xlink:href=\"../images/a%25%23%3F%20%01%FF%C3%A9.png\""
   OR NOT json MATCHES "${name_start}5c7530303031efbfbdc3a92e706e67")  # \u0001, U+FFFD, é.png
  message(FATAL_ERROR "odd name (${rc}): the link or the JSON string is wrong: ${err}")
endif()
if(PYTHON)  # parsed as XML and JSON, the link followed from the SVG's folder
  execute_process(COMMAND ${PYTHON} -c [[
import json, os, sys, urllib.parse, xml.dom.minidom
svg, data, image = sys.argv[1:4]
href = xml.dom.minidom.parse(svg).getElementsByTagName("image")[0].getAttribute("xlink:href")
link = os.path.join(os.path.dirname(svg).encode(), urllib.parse.unquote_to_bytes(href))
json.loads(open(data, "rb").read().decode("utf-8"))
sys.exit(0 if os.path.samefile(link, image.encode("utf-8", "surrogateescape")) else 1)]]
                  ${WORK}/drawings/odd.svg ${WORK}/odd.json "${WORK}/images/${odd}" RESULT_VARIABLE parsed ERROR_VARIABLE why)
  if(NOT parsed EQUAL 0)
    message(FATAL_ERROR "odd name: the SVG or the JSON does not parse, or the link does not lead to the image: ${why}")
  endif()
endif()

# A drawing is 1024 pixels on the region's longer side (a 1 x 1024 PNG here,
# where it was 1024 x 1,024,000).
run_mesh(--density ramp --points 100 --region 0 0 0.001 1 --png ${WORK}/narrow.png)
file(READ ${WORK}/narrow.png size HEX OFFSET 16 LIMIT 8)
if(NOT rc EQUAL 0 OR NOT size STREQUAL "0000000100000400")
  message(FATAL_ERROR "--region 0 0 0.001 1 --png: status ${rc}, IHDR size ${size}: ${err}")
endif()

# Options whose values overflow the density are named (status 2).
set(option_cases
  "--terrain|${DATA}/terrain.png|--height-scale|1e305|heights of [^\n]*terrain.png times it overflow"
  "--terrain|${DATA}/terrain.png|--gamma|1e10|density of [^\n]*terrain.png raised to it overflows"
  "--density|radial|--gamma|1e300|radial density raised to it overflows"
  "--density|constant|--region|-1e308 0 1e308 1|must be positive and finite"
  "--terrain|${DATA}/terrain.png|--max-pixels|0|must be in"
  "--gamma|1|--density|image:|needs a file name")
foreach(c ${option_cases})
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 input)
  list(GET c 1 value)
  list(GET c 2 option)
  list(GET c 3 option_value)
  list(GET c 4 why)
  separate_arguments(option_value)
  run_mesh(${input} ${value} --points 100 ${option} ${option_value})
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: [^\n]*${option}[^\n]*${why}[^\n]*\n$")
    message(FATAL_ERROR "${input} ${value} ${option} ${option_value}: expected status 2 and one line, got ${rc}: ${err}")
  endif()
endforeach()

# --max-error: every cell within it, or --points vertices if fewer; bad
# values of the terrain options are named (status 2).
foreach(points 0 5000)
  set(budget)
  if(points)
    set(budget --points ${points})
  endif()
  run_mesh(--terrain ${DATA}/terrain.png --max-error 300 ${budget} --stats-json ${WORK}/max_error.json)
  file(READ ${WORK}/max_error.json json)
  json_number("${json}" max_error max)
  json_number("${json}" vertices vertices)
  if(NOT rc EQUAL 0 OR (NOT points AND (max GREATER 300 OR NOT json MATCHES "\"max_error_reached\": true"))
     OR (points AND (NOT vertices EQUAL points OR NOT max GREATER 300 OR NOT json MATCHES "\"max_error_reached\": false")))
    message(FATAL_ERROR "--max-error 300 ${budget}: status ${rc}, ${vertices} vertices, max error ${max}: ${err}")
  endif()
endforeach()
# An image's luminance refined to 0.05: fewer vertices than pixels, above the grid.
run_mesh(--density image:${DATA}/test_image.png --max-error 0.05 --stats-json ${WORK}/image_max_error.json)
file(READ ${WORK}/image_max_error.json json)
json_number("${json}" vertices vertices)
json_number("${json}" psnr psnr)
json_number("${json}" grid_psnr grid_psnr)
if(NOT rc EQUAL 0 OR NOT json MATCHES "\"max_error_reached\": true" OR NOT vertices LESS 26214
   OR NOT psnr GREATER grid_psnr)
  message(FATAL_ERROR "image --max-error 0.05: status ${rc}, ${vertices} vertices, PSNR ${psnr} (grid ${grid_psnr}): ${err}")
endif()

# --fit-heights lowers the RMS error of the mesh, which no longer interpolates the heights.
run_mesh(--terrain ${DATA}/terrain.png --points 5000 --fit-heights --stats-json ${WORK}/fit.json)
file(READ ${WORK}/fit.json json)
json_number("${json}" rms_error rms)
json_number("${json}" fit_rms_error_before before)
json_number("${json}" fit_rms_error_after after)
if(NOT rc EQUAL 0 OR NOT rms LESS before OR NOT after LESS before)
  message(FATAL_ERROR "--fit-heights: status ${rc}, rms error ${rms} (measured), ${before} -> ${after} (fit): ${err}")
endif()

# The border is on by default for terrains (and images), off with --no-boundary.
foreach(option "" --no-boundary)
  run_mesh(--terrain ${DATA}/terrain.png --points 2000 ${option} --stats-json ${WORK}/border.json)
  file(READ ${WORK}/border.json json)
  json_number("${json}" boundary_points border)
  if(NOT rc EQUAL 0 OR (option AND NOT border EQUAL 0) OR (NOT option AND border LESS 20))
    message(FATAL_ERROR "--terrain ${option}: status ${rc}, ${border} border points: ${err}")
  endif()
endforeach()
# Bad values of the terrain options and of --tiles and --tile are named
# (status 2), and no tile is written.
foreach(c "--max-error 0|--max-error must be positive" "--max-error -1|--max-error must be positive"
          "--max-error nan|--max-error expects a number" "--base-fraction 0|--base-fraction must be in"
          "--base-fraction 1.5|--base-fraction must be in" "--boundary --no-boundary|--no-boundary, not both"
          "--max-error 1 --base-fraction 0.5|--base-fraction is a fraction of --points"
          "--max-error 300 --fit-heights|--fit-heights and --max-error: give one"
          "--tiles 0|--tiles must be a whole number from 1 to 1024" "--tiles 2.5|--tiles must be a whole number"
          "--tiles 100 --out-mesh ${WORK}/t.off|--tiles 100 makes tiles of fewer than 8 x 8 cells"
          "--tiles 3 --tile 3 0 --out-mesh ${WORK}/t.off|--tile I J must be within 0..2 for --tiles 3"
          "--tiles 3 --tile 0 -1 --out-mesh ${WORK}/t.off|--tile must be a whole number"
          "--tile 0 0 --out-mesh ${WORK}/t.off|--tile I J needs --tiles K"
          "--tiles 3 --tile 0 0|--tile needs --out-mesh" "--tiles 3|--tiles needs --out-mesh"
          "--tiles 3 --out-mesh ${WORK}/t.off --svg ${WORK}/t.svg|--svg does not apply to --tiles"
          "--tiles 3 --out-mesh ${WORK}/t.off --no-boundary|--no-boundary does not apply to --tiles"
          "--tiles 3 --out-mesh ${WORK}/t.off --fit-heights|--fit-heights does not apply to --tiles")
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 options)
  list(GET c 1 why)
  separate_arguments(options)
  run_mesh(--terrain ${DATA}/terrain.png ${options})
  file(GLOB written ${WORK}/t_*)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: [^\n]*${why}[^\n]*\n$" OR written)
    message(FATAL_ERROR "${options}: expected status 2 and one line, got ${rc}: ${err} ${written}")
  endif()
endforeach()
run_mesh(--density constant --max-error 1)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--max-error and --base-fraction apply to --terrain and images")
  message(FATAL_ERROR "--density constant --max-error 1: got ${rc}: ${err}")
endif()
foreach(options "image:${DATA}/test_image.png" "image:${DATA}/test_image.png;--log;--reconstruct;${WORK}/r.png" constant)
  run_mesh(--density ${options} --fit-heights)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: --fit-heights applies to --terrain[^\n]*\n$")
    message(FATAL_ERROR "--density ${options} --fit-heights: got ${rc}: ${err}")
  endif()
endforeach()
run_mesh(--density image:${DATA}/test_image.png --base-fraction 0.5)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--base-fraction applies to an image with --max-error")
  message(FATAL_ERROR "image --base-fraction 0.5: got ${rc}: ${err}")
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

# A PGM whose sample exceeds its maxval (1, the sample '2') is refused; an
# old-style run-length Radiance file is read (a pixel and a run of 3);
# control bytes of an echoed header are escaped: one printable line.
file(WRITE ${WORK}/maxval.pgm "P5\n1 1\n1\n2")
run_mesh(--density image:${WORK}/maxval.pgm)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^penrose_mesh: [^\n]*maxval.pgm: sample 0 is 50, more than the maxval 1\n$")
  message(FATAL_ERROR "maxval.pgm: expected status 1 naming the file, got ${rc}: ${err}")
endif()
string(ASCII 1 one)
string(ASCII 3 three)
file(WRITE ${WORK}/old_rle.hdr "#?RADIANCE\n\n-Y 1 +X 4\nABCx${one}${one}${one}${three}")
run_mesh(--density image:${WORK}/old_rle.hdr --points 10 --out-points ${WORK}/old_rle.xy)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "old-style run-length encoded Radiance file: got ${rc}: ${err}")
endif()
string(ASCII 27 escape)
string(ASCII 12 form_feed)
file(WRITE ${WORK}/control.hdr "#?RADIANCE\nFORMAT=${escape}[31mred${form_feed}\r\n\n-Y 1 +X 1\n\n")
run_mesh(--density image:${WORK}/control.hdr)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^penrose_mesh: [^\n]*control.hdr: [^\n]*unsupported FORMAT=\\\\x1b\\[31mred\\\\x0c\\\\x0d\\)\n$")
  message(FATAL_ERROR "control.hdr: expected one printable line, got ${rc}: ${err}")
endif()

# A flat terrain, and a black image meshed for --reconstruct, have a zero
# density: their sample is uniform, and they make a mesh.
file(WRITE ${WORK}/flat.asc "ncols 12\nnrows 10\nxllcorner 0\nyllcorner 0\ncellsize 1\n")
foreach(j RANGE 9)
  file(APPEND ${WORK}/flat.asc "5 5 5 5 5 5 5 5 5 5 5 5\n")
endforeach()
file(WRITE ${WORK}/black.pgm "P5\n16 12\n255\n")
execute_process(COMMAND sh -c "head -c 192 /dev/zero >> black.pgm" WORKING_DIRECTORY ${WORK})
foreach(input "--terrain;${WORK}/flat.asc" "--density;image:${WORK}/black.pgm;--reconstruct;${WORK}/black.png")
  run_mesh(${input} --points 60 --out-mesh ${WORK}/flat.off)
  file(STRINGS ${WORK}/flat.off counts LIMIT_COUNT 2)
  list(GET counts 1 counts)
  if(NOT rc EQUAL 0 OR NOT counts MATCHES "^[1-9][0-9]* [1-9][0-9]* 0$")
    message(FATAL_ERROR "${input}: expected a mesh, got ${rc} (${counts}): ${err}")
  endif()
endforeach()

# A viewer far away weights the density almost uniformly (it underflowed to
# zero); one whose distances overflow is named. Too many tiles for the
# points, more points than a grid refined greedily has cells, and a --gamma
# that makes the density zero are refused by name (status 2).
file(WRITE ${WORK}/grey.pgm "P5\n4 4\n255\n@@@@@@@@@@@@@@@@")
run_mesh(--terrain ${DATA}/terrain.png --points 100 --viewer 1e308 1e308 --out-mesh ${WORK}/viewer.off)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--viewer 1e308 1e308: got ${rc}: ${err}")
endif()
foreach(c "--terrain;${DATA}/terrain.png;--viewer;1.7e308;1.7e308|--viewer 1.7e\\+308 1.7e\\+308: its distances to the region overflow"
          "--density;ramp;--points;100;--tiles;1024;--out-mesh;${WORK}/t.off|--tiles 1024 makes 1048576 tiles for about 100 vertices"
          "--terrain;${WORK}/flat.asc;--points;1e9|--points 1e\\+09 is more than the 120 cells of [^\n]*flat.asc"
          "--terrain;${WORK}/flat.asc;--points;1000|--points 1000 is more than the 120 cells of [^\n]*flat.asc"
          "--density;image:${WORK}/grey.pgm;--gamma;1e6|--gamma 1e\\+06: the density of [^\n]*grey.pgm raised to it is zero")
  string(REPLACE "|" ";" c "${c}")
  list(POP_BACK c why)
  run_mesh(${c})
  file(GLOB written ${WORK}/t_*)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: ${why}[^\n]*\n$" OR written)
    message(FATAL_ERROR "${c}: expected status 2 and one line about '${why}', got ${rc}: ${err}")
  endif()
endforeach()
