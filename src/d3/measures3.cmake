# The 3-D measures of cfpo3d-analyze beyond delta and Q6: the power
# spectrum (NUFFT and direct sum), its shells and P0, and g(r). Included by
# CMakeLists.txt; tests against brute force (tests/d3/test_d3_measures.c).
add_library(cfpo_d3m STATIC measures3_spec.c measures3_pcf.c measures3_w6.c)
target_include_directories(cfpo_d3m PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(cfpo_d3m PUBLIC cfpo_d3)
target_link_libraries(cfpo3d-analyze PRIVATE cfpo_d3m)

add_executable(test_d3_measures ${PROJECT_SOURCE_DIR}/tests/d3/test_d3_measures.c)
target_include_directories(test_d3_measures PRIVATE ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(test_d3_measures PRIVATE cfpo_d3m)
# (registered in baselines/d3.cmake: tests are enabled after src/d3 is read)

# The Voronoi cells on CGAL's periodic 3-D triangulation (faces per cell,
# volumes, centroids) and the FPD certificate: cfpo3d-analyze --voronoi and
# --certify, and 3-D Lloyd, where CGAL is.
if(CFPO_HAVE_CGAL)
  add_library(cfpo_d3vor STATIC measures3_vor.cpp measures3_fpd.cpp)
  target_include_directories(cfpo_d3vor PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(cfpo_d3vor PUBLIC cfpo_d3 CGAL::CGAL)
  target_link_libraries(cfpo3d-analyze PRIVATE cfpo_d3vor)
  target_compile_definitions(cfpo3d-analyze PRIVATE CFPO3_HAVE_VORONOI=1)
  add_executable(test_d3_voronoi ${PROJECT_SOURCE_DIR}/tests/d3/test_d3_voronoi.c)
  target_include_directories(test_d3_voronoi PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(test_d3_voronoi PRIVATE cfpo_d3vor cfpo_d3)
endif()
