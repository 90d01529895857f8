# ctest -> cmake -P: install SliceMesh from BUILD_DIR into a fresh prefix under WORK_DIR, check the
# layout (CLI module folder, headers, package files), then configure, build and run the consumer
# project against that prefix. Arguments: BUILD_DIR, SOURCE_DIR (the consumer), WORK_DIR, CLI_DIR,
# CXX_COMPILER, BUILD_TYPE, CONSUMER_FLAGS (compile and link flags for the consumer, e.g. sanitizers).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

# The whole install, as a user runs it (components: Runtime = the CLI module, Development = the library).
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file ${CLI_DIR}/SliceMesh ${CLI_DIR}/SliceMesh.xml ${CLI_DIR}/SliceMeshPlugins/libSliceMeshImageDicom.so
             ${CLI_DIR}/SliceMeshPlugins/libSliceMeshStructuresDicom.so
             ${CLI_DIR}/SliceMeshPlugins/libSliceMeshSnapshotRendering.so include/slicemesh/Meshing/MeshContours.h
             include/slicemesh/Tiling/SurfaceReconstruction.h include/slicemesh/Core/SliceMeshTypes.h
             lib/libSliceMeshLogic.a lib/cmake/SliceMesh/SliceMeshConfig.cmake
             lib/cmake/SliceMesh/SliceMeshConfigVersion.cmake lib/cmake/SliceMesh/SliceMeshTargets.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${prefix}/${file}")
  endif()
endforeach()
# Headers internal to a stage stay out; none is flat in include/.
foreach(file include/slicemesh/Tiling/SlabTiling.h include/slicemesh/Core/DisjointSets.h include/SliceMesh
             include/MeshValidation.h)
  if(EXISTS ${prefix}/${file})
    message(FATAL_ERROR "installed but internal or flat: ${prefix}/${file}")
  endif()
endforeach()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/consumer-build -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer-build)
run(${WORK_DIR}/consumer-build/consumer)
message(STATUS "installed SliceMesh found, linked and run by the consumer project")
