# Installs SliceMesh's Logic library as a CMake package: headers in include/slicemesh/<Stage>/, the static
# library in lib, and SliceMeshConfig.cmake + SliceMeshConfigVersion.cmake + the exported targets in
# lib/cmake/SliceMesh, so another project can find_package(SliceMesh) and link SliceMesh::Logic.
# Component "Development"; the CLI module (CLI/CMakeLists.txt) is component "Runtime".
include(CMakePackageConfigHelpers)

set(SLICEMESH_INCLUDE_INSTALL_DIR include)
set(SLICEMESH_PACKAGE_INSTALL_DIR lib/cmake/SliceMesh)

set_target_properties(SliceMeshLogic PROPERTIES EXPORT_NAME Logic)
install(TARGETS SliceMeshLogic EXPORT SliceMeshTargets
  ARCHIVE DESTINATION lib COMPONENT Development
  LIBRARY DESTINATION lib COMPONENT Development
  INCLUDES DESTINATION ${SLICEMESH_INCLUDE_INSTALL_DIR})
# The stages' public headers, by stage (CGAL stays inside the .cxx files). Headers internal to a
# stage (its helpers and data structures) are not installed; no public header includes one.
set(SLICEMESH_INTERNAL_HEADERS
  Core/DisjointSets.h Core/SpatialHash.h Core/NearestSegment.h Core/ArcLengthWalk.h
  Contours/ContourCrossings.h
  Correspondence/PolygonProximity.h Correspondence/MutualIntersections.h
  Finishing/RemeshingRegions.h Finishing/PieceTargetVolumes.h Finishing/PieceRejection.h Finishing/PutBackVertices.h
  Finishing/CrossingPlaces.h Finishing/FinishedPieceRepair.h Finishing/PackedTaubinSteps.h
  Measures/SurfaceMeshConversion.h Measures/TriangleMeshTree.h
  Tiling/SlabTiling.h Tiling/SlabOverlayState.h Tiling/MeshBuilder.h)
file(GLOB SLICEMESH_LOGIC_HEADERS RELATIVE ${PROJECT_SOURCE_DIR}/Logic ${PROJECT_SOURCE_DIR}/Logic/*/*.h)
list(REMOVE_ITEM SLICEMESH_LOGIC_HEADERS ${SLICEMESH_INTERNAL_HEADERS})
foreach(header ${SLICEMESH_LOGIC_HEADERS})
  get_filename_component(stage ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/Logic/${header} DESTINATION ${SLICEMESH_INCLUDE_INSTALL_DIR}/slicemesh/${stage}
    COMPONENT Development)
endforeach()
install(EXPORT SliceMeshTargets NAMESPACE SliceMesh:: DESTINATION ${SLICEMESH_PACKAGE_INSTALL_DIR}
  COMPONENT Development)

configure_package_config_file(${PROJECT_SOURCE_DIR}/CMake/SliceMeshConfig.cmake.in
  ${PROJECT_BINARY_DIR}/SliceMeshConfig.cmake
  INSTALL_DESTINATION ${SLICEMESH_PACKAGE_INSTALL_DIR}
  PATH_VARS SLICEMESH_INCLUDE_INSTALL_DIR)
# 0.x: minor versions may break the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SliceMeshConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SliceMeshConfig.cmake ${PROJECT_BINARY_DIR}/SliceMeshConfigVersion.cmake
  DESTINATION ${SLICEMESH_PACKAGE_INSTALL_DIR} COMPONENT Development)
