# penrose_mesh (PENROSE_MESH) never loses a file: an output that is the
# input or another output is refused before anything is read (status 2, the
# option named, the input untouched), and an output replaces the previous
# file only once complete, even when the run is killed while writing. WORK
# is a scratch folder; DATA holds the bundled inputs.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run_mesh)
  execute_process(COMMAND ${PENROSE_MESH} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET
                  WORKING_DIRECTORY ${WORK})
  set(rc "${rc}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# Status 2 and one line that matches `why`.
function(expect_refusal why)
  run_mesh(${ARGN})
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: ${why}[^\n]*\n$")
    message(FATAL_ERROR "${ARGN}: expected status 2 and one line matching '${why}', got ${rc}: ${err}")
  endif()
endfunction()

# An input named as an output, directly, through ./, an absolute path, a
# symbolic link or a hard link, by each output that applies to it.
file(WRITE ${WORK}/g.asc "ncols 12\nnrows 10\nxllcorner 0\nyllcorner 0\ncellsize 1\n")
foreach(j RANGE 9)
  file(APPEND ${WORK}/g.asc "0 1 2 3 4 5 6 7 8 9 10 ${j}\n")
endforeach()
file(COPY_FILE ${DATA}/test_image.png ${WORK}/i.png)
foreach(input g.asc i.png)
  file(CREATE_LINK ${input} ${WORK}/symbolic_${input} SYMBOLIC)
  file(CREATE_LINK ${WORK}/${input} ${WORK}/hard_${input})
  file(SHA256 ${WORK}/${input} before)
  if(input STREQUAL "g.asc")
    set(read --terrain ${input})
    set(read_text "--terrain ${input}")
    set(outputs --out-points --out-mesh --svg --png --stats-json)
  else()
    set(read --density image:${input})
    set(read_text "--density image:${input}")
    set(outputs --out-points --out-mesh --svg --png --reconstruct --stats-json)
  endif()
  foreach(option ${outputs})
    foreach(name ${input} ./${input} ${WORK}/${input} symbolic_${input} hard_${input})
      expect_refusal("${option} ${name} is the input file \\(${read_text}\\)" ${read} --points 50 ${option} ${name})
    endforeach()
  endforeach()
  # also when the output comes first on the command line
  expect_refusal("--out-points ${input} is the input file" --out-points ${input} ${read})
  file(SHA256 ${WORK}/${input} after)
  if(NOT after STREQUAL before)
    message(FATAL_ERROR "${input} was changed by a refused run")
  endif()
endforeach()

# A tile of --tiles that is the input (through a link, the only way: the
# tiles' names end in _I_J).
file(CREATE_LINK ${DATA}/terrain.png ${WORK}/t_1_0.png SYMBOLIC)
expect_refusal("--out-mesh t.png: tile 1 0, t_1_0.png, is the input file \\(--terrain ${DATA}/terrain.png\\)"
               --terrain ${DATA}/terrain.png --tiles 2 --out-mesh t.png)
expect_refusal("--out-mesh t.png: tile 1 0" --terrain ${DATA}/terrain.png --tiles 2 --tile 1 0 --out-mesh t.png)

# Two outputs on one path, new or existing, however spelled: nothing written.
foreach(pair "m.off;./m.off" "${WORK}/m.off;m.off")
  list(GET pair 0 first)
  list(GET pair 1 second)
  expect_refusal("--svg ${second} and --out-mesh ${first} are the same file"
                 --density ramp --points 50 --out-mesh ${first} --svg ${second})
  if(EXISTS ${WORK}/m.off)
    message(FATAL_ERROR "a refused run wrote m.off")
  endif()
endforeach()
file(WRITE ${WORK}/old.json "{}\n")
file(CREATE_LINK ${WORK}/old.json ${WORK}/hard.json)
expect_refusal("--stats-json hard.json and --out-points old.json are the same file"
               --density ramp --points 50 --out-points old.json --stats-json hard.json)
# Devices are not files that a run could lose: outputs may share /dev/null.
run_mesh(--density ramp --points 50 --out-points /dev/null --stats-json /dev/null)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--out-points /dev/null --stats-json /dev/null: got ${rc}: ${err}")
endif()

# An empty file name is refused by name (it was taken for no output at all).
# (execute_process here: a list passed on to a function drops its empty items)
foreach(option --terrain --out-points --out-mesh --svg --png --reconstruct --stats-json)
  execute_process(COMMAND ${PENROSE_MESH} --density image:i.png ${option} "" WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "^penrose_mesh: ${option} needs a file name, not ''[^\n]*\n$")
    message(FATAL_ERROR "${option} '': expected status 2 naming the option, got ${rc}: ${err}")
  endif()
endforeach()

# A complete run replaces the file; one killed while writing leaves it as it
# was. The kill is deterministic: the file size limit sends SIGXFSZ at the
# 65,537th byte of the points; with the signal ignored, the write fails
# (status 1) and the temporary file is removed.
run_mesh(--density ramp --points 100 --out-points points.xy)
file(SHA256 ${WORK}/points.xy old)
file(STRINGS ${WORK}/points.xy lines)
list(LENGTH lines old_lines)
execute_process(COMMAND prlimit --fsize=65536 ${PENROSE_MESH} --density ramp --points 20000 --out-points points.xy
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
file(SHA256 ${WORK}/points.xy now)
file(GLOB left ${WORK}/.points.xy.*.tmp)
list(LENGTH left left_count)
if(rc EQUAL 0 OR NOT now STREQUAL old OR NOT left_count EQUAL 1)
  message(FATAL_ERROR "killed by SIGXFSZ (${rc}): points.xy changed or no temporary file left (${left}): ${err}")
endif()
file(SIZE ${left} size)
if(NOT size EQUAL 65536)
  message(FATAL_ERROR "the run was not killed while writing: ${size} bytes in ${left}")
endif()
file(REMOVE ${left})
execute_process(COMMAND sh -c "trap '' XFSZ; exec prlimit --fsize=65536 \"$0\" --density ramp --points 20000 --out-points points.xy"
                        ${PENROSE_MESH}
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc ERROR_VARIABLE err)
file(SHA256 ${WORK}/points.xy now)
file(GLOB left ${WORK}/.points.xy.*)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^penrose_mesh: points.xy: cannot write \\(File too large\\)\n$"
   OR NOT now STREQUAL old OR left)
  message(FATAL_ERROR "a failed write (${rc}: ${err}) changed points.xy or left ${left}")
endif()

# SIGKILL at a moment the test does not choose exactly: as soon as the
# temporary file holds bytes. points.xy is then the old file, or, if the run
# ended first, the new one complete; never anything else.
run_mesh(--density ramp --points 300000 --out-points complete.xy)
file(SHA256 ${WORK}/complete.xy new)
execute_process(COMMAND sh -c [[
"$0" --density ramp --points 300000 --out-points points.xy 2> /dev/null &
pid=$!
while kill -0 $pid 2> /dev/null; do
  for f in .points.xy.*.tmp; do
    if [ -s "$f" ]; then kill -KILL $pid; echo killed; exit 0; fi
  done
  sleep 0.001
done
echo ended]] ${PENROSE_MESH} WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE outcome OUTPUT_STRIP_TRAILING_WHITESPACE)
file(SHA256 ${WORK}/points.xy now)
if(NOT (outcome STREQUAL "killed" AND now STREQUAL old) AND NOT (outcome STREQUAL "ended" AND now STREQUAL new))
  message(FATAL_ERROR "SIGKILL while writing (${outcome}): points.xy is neither the old file nor the new one")
endif()
message(STATUS "SIGKILL: ${outcome}")

# Readers never read without bound: devices, an endless pipe and endless
# data after a small header end with status 1 in a few seconds at most,
# under 100 MB of address space (the old reader held 2.2 GB after 4 s): LIMIT
# is the command that sets it (empty under AddressSanitizer).
function(run_bounded command expected)
  execute_process(COMMAND sh -c "${command}" ${PENROSE_MESH} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "^penrose_mesh: [^\n]*${expected}[^\n]*\n$")
    message(FATAL_ERROR "${command}: expected status 1 and one line matching '${expected}', got ${rc}: ${err}")
  endif()
endfunction()
string(REPLACE ";" " " limit "${LIMIT}")
set(bounded "timeout 5 ${limit} \"$0\"")
foreach(device /dev/zero /dev/urandom)
  run_bounded("${bounded} --terrain ${device}" "${device}: ")
  run_bounded("${bounded} --density image:${device}" "${device}: ")
endforeach()
run_bounded("yes | ${bounded} --terrain /dev/stdin" "/dev/stdin: cannot read as an image \\(not a PNG")
run_bounded("yes | ${bounded} --density image:/dev/stdin" "/dev/stdin: cannot read as an image \\(not a PNG")
# A grid of 12 x 10 cells followed by endless rows, through a named pipe.
execute_process(COMMAND mkfifo ${WORK}/endless.asc)
run_bounded("(printf 'ncols 12\\nnrows 10\\nxllcorner 0\\nyllcorner 0\\ncellsize 1\\n'; yes 0 1 2 3 4 5 6 7 8 9 10 11) > endless.asc 2> /dev/null &
             ${bounded} --terrain endless.asc"
            "endless.asc: more than the 7733 bytes that its 12 x 10 cells at 64 bytes a cell can take")
# A PNG and a JPEG whose headers start endless zeros: the PNG is of 4 x 4 pixels, the JPEG's size never comes.
run_bounded("(printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\rIHDR\\0\\0\\0\\4\\0\\0\\0\\4\\10\\0\\0\\0\\0'; cat /dev/zero) | ${bounded} --terrain /dev/stdin"
            "/dev/stdin: more than the [0-9]+ bytes that its 4 x 4 pixels can take")
run_bounded("(printf '\\377\\330\\377'; cat /dev/zero) | ${bounded} --density image:/dev/stdin"
            "/dev/stdin: cannot read as an image \\(no complete header in its first 16 MiB\\)")
