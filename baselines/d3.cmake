# The 3-D baselines (bl3.h; baselines/README.md, "Three dimensions"):
# white, jittered, dart throwing, Bridson and weighted sample elimination
# in C, FPO on CGAL's periodic 3-D Delaunay triangulation where CGAL is.
# Commands cfpo3d-<method> beside cfpo3d. Included by CMakeLists.txt.
add_library(cfpo_bl3 STATIC bl3_cli.c bl3_direct.c pd3grid.c dart3.c bridson3.c wse3.c)
target_include_directories(cfpo_bl3 PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(cfpo_bl3 PUBLIC cfpo_d3 cfpo_iter)

foreach(m white jitter dart bridson wse)
  cfpo_baseline_exe(cfpo3d-${m} main3_direct.c)
  target_link_libraries(cfpo3d-${m} PRIVATE cfpo_bl3)
  target_compile_definitions(cfpo3d-${m} PRIVATE BL3_METHOD=bl3_${m})
endforeach()

cfpo_baseline_unit(test_bl3 cfpo_bl3)

if(CFPO_HAVE_CGAL)
  add_library(cfpo_bl3_cgal STATIC fpo3.cpp)
  target_link_libraries(cfpo_bl3_cgal PUBLIC cfpo_bl3 CGAL::CGAL)
  cfpo_baseline_exe(cfpo3d-fpo main3_direct.c)
  target_link_libraries(cfpo3d-fpo PRIVATE cfpo_bl3_cgal)
  target_compile_definitions(cfpo3d-fpo PRIVATE BL3_METHOD=bl3_fpo)
  add_library(cfpo_bl3_lloyd STATIC lloyd3.c)
  target_link_libraries(cfpo_bl3_lloyd PUBLIC cfpo_bl3 cfpo_d3vor)
  cfpo_baseline_exe(cfpo3d-lloyd main3_direct.c)
  target_link_libraries(cfpo3d-lloyd PRIVATE cfpo_bl3_lloyd)
  target_compile_definitions(cfpo3d-lloyd PRIVATE BL3_METHOD=bl3_lloyd)
  add_test(NAME test_d3_voronoi COMMAND test_d3_voronoi)
  set_tests_properties(test_d3_voronoi PROPERTIES LABELS unit)
endif()

add_test(NAME baselines_cli3d COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tests/test_cli3d.sh ${CMAKE_BINARY_DIR})
set_tests_properties(baselines_cli3d PROPERTIES LABELS cli)

# The 3-D measures' unit test (built in src/d3/measures3.cmake).
add_test(NAME test_d3_measures COMMAND test_d3_measures)
set_tests_properties(test_d3_measures PROPERTIES LABELS unit)
add_test(NAME test_d3_analyze_cli COMMAND ${PROJECT_SOURCE_DIR}/tests/d3/test_d3_analyze_cli.sh ${CMAKE_BINARY_DIR})
set_tests_properties(test_d3_analyze_cli PROPERTIES LABELS cli)
