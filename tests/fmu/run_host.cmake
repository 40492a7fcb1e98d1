# Exports a law FMU (the seed tire, rolling) and the gear FMU with contensou-fmu, unpacks them
# and runs the C host (fmu_host.c) on the unpacked folders.
# -DEXPORTER=... -DHOST=... -DWORK=...
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/law ${WORK}/gear)
execute_process(COMMAND ${EXPORTER} law -o ${WORK}/law.fmu --radius 0.087 --pressure 2.1e5
                        --profile seed-tire --friction 0.3 --kx 0.14 --ky 0.05 --kappa 0.8
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contensou-fmu law failed: ${rc}")
endif()
execute_process(COMMAND ${EXPORTER} gear -o ${WORK}/gear.fmu RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contensou-fmu gear failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${WORK}/law.fmu WORKING_DIRECTORY ${WORK}/law)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${WORK}/gear.fmu WORKING_DIRECTORY ${WORK}/gear)
execute_process(COMMAND ${HOST} ${WORK}/law ${WORK}/gear ${WORK} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fmu_host failed: ${rc}")
endif()
