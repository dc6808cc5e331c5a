# The unperturbed rows (realisation 0) of the tiny campaign equal single
# `assess rocking --json` runs of the same wall, record, scale and model.
# -DEXE=assess -DSRC=source dir -DOUT=work dir
# Tolerance: the two print the same double computation, the CSV with 10
# significant digits, so they agree to a relative 1e-8 (-).
set(rel_tol 1e-8)
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} campaign ${SRC}/tests/data/campaign/tiny.json --out ${OUT} --limit 2 --quiet --no-plots
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "campaign failed: ${err}")
endif()
file(STRINGS ${OUT}/results.csv lines)
list(GET lines 0 header)
string(REPLACE "," ";" header "${header}")
foreach(row 1 2)
  list(GET lines ${row} line)
  # Empty fields (k of the rigid model) become "-": CMake lists drop nothing, but
  # an empty element would be lost by the unquoted expansions below.
  string(REPLACE ",," ",-," line "${line}")
  string(REPLACE ",," ",-," line "${line}")
  string(REPLACE "," ";" f "${line}")
  foreach(col wall model scale unit_weight_kN_m3 k_kN_m3 realisation theta_max_rad dc_energy impacts overturned)
    list(FIND header ${col} i)
    list(GET f ${i} ${col})
  endforeach()
  # tiny.json: realisation 0 of wall w1 (b, h) = (0.125, 1.5) m under Sturno WE.
  if(NOT realisation EQUAL 0 OR NOT wall STREQUAL "w1")
    message(FATAL_ERROR "row ${row} is not the unperturbed record on wall w1")
  endif()
  set(args rocking --model ${model} --thickness 0.25 --height 3 --unit-weight ${unit_weight_kN_m3}
      --restitution housner --record ${SRC}/spectra/records/RSN292_ITALY_A-STU270.AT2 --scale ${scale} --json)
  if(model STREQUAL "smooth")
    list(APPEND args --k ${k_kN_m3})
  endif()
  execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "assess rocking failed: ${err}")
  endif()
  string(JSON j_theta_max_rad GET "${json}" theta_max)
  string(JSON j_dc_energy GET "${json}" dc)
  string(JSON j_impacts GET "${json}" impacts)
  string(JSON j_overturned GET "${json}" overturned)
  if(NOT j_impacts EQUAL impacts)
    message(FATAL_ERROR "${model}: impacts ${impacts} (campaign) vs ${j_impacts} (rocking)")
  endif()
  if(j_overturned)
    set(j_overturned 1)
  else()
    set(j_overturned 0)
  endif()
  if(NOT j_overturned EQUAL overturned)
    message(FATAL_ERROR "${model}: overturned ${overturned} (campaign) vs ${j_overturned} (rocking)")
  endif()
  foreach(name theta_max_rad dc_energy)
    # CMake has no floating point: awk checks |a - b| <= rel_tol |b|.
    execute_process(COMMAND awk -v a=${${name}} -v b=${j_${name}} -v t=${rel_tol}
      "BEGIN { d = a - b; if (d < 0) d = -d; r = b < 0 ? -b : b; exit !(d <= t * r) }" RESULT_VARIABLE close)
    if(NOT close EQUAL 0)
      message(FATAL_ERROR "${model} ${name}: ${${name}} (campaign) vs ${j_${name}} (rocking), rel tol ${rel_tol}")
    endif()
  endforeach()
  message(STATUS "${model}: theta_max ${theta_max_rad} rad, D/C ${dc_energy}, ${impacts} impacts: as assess rocking")
endforeach()
