# penrose_mesh --streamed (PENROSE_MESH), checked with mesh_check
# (MESH_CHECK), in WORK: the PLY written window by window is CGAL's
# triangulation of its points, for densities with a zero (the ramp's left
# side), a peak and holes of an image, over many windows; a window size
# that makes a single window gives the same triangles; bad uses are refused
# with status 2 and the option named.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(expect_delaunay)
  execute_process(COMMAND ${PENROSE_MESH} ${ARGN} --streamed --out-mesh ${WORK}/s.ply
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "penrose_mesh ${ARGN} --streamed: status ${rc}: ${err}")
  endif()
  execute_process(COMMAND ${MESH_CHECK} delaunay ${WORK}/s.ply OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "penrose_mesh ${ARGN} --streamed: not CGAL's triangulation: ${out}")
  endif()
  message(STATUS "${ARGN}: ${out}")
endfunction()

expect_delaunay(--density ramp --points 60000 --window-points 2000)
expect_delaunay(--density radial --points 60000 --window-points 700 --region -3 -1 5 2)
expect_delaunay(--density constant --points 20000 --no-correction --window-points 1000)
expect_delaunay(--density image:${DATA}/test_image.png --gamma 3 --no-boundary --points 30000 --window-points 1500)
# a sub-window of the file against CGAL's triangulation of the points around it
execute_process(COMMAND ${MESH_CHECK} delaunay ${WORK}/s.ply 100 80 160 120 OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "a sub-window of the image's streamed mesh is not CGAL's: ${out}")
endif()

# the option's name, then the command line
function(expect_usage_error option)
  execute_process(COMMAND ${PENROSE_MESH} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${option}")
    message(FATAL_ERROR "penrose_mesh ${ARGN}: status ${rc}, expected 2 naming ${option}: ${err}")
  endif()
endfunction()
expect_usage_error(--streamed --streamed --density ramp --out-mesh ${WORK}/x.off)
expect_usage_error(--streamed --streamed --density ramp --out-mesh ${WORK}/x.ply --svg ${WORK}/x.svg)
expect_usage_error(--streamed --streamed --terrain ${DATA}/terrain.png --out-mesh ${WORK}/x.ply)
expect_usage_error(--streamed --streamed --density ramp --boundary --out-mesh ${WORK}/x.ply)
expect_usage_error(--window-points --density ramp --window-points 100 --out-mesh ${WORK}/x.ply)
expect_usage_error(--window-points --streamed --density ramp --window-points 3 --out-mesh ${WORK}/x.ply)
