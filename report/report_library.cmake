# `report`: everything `slamsweep report` needs. The plot and image libraries are linked when
# their folders exist; otherwise the report is built without images (pages say so).
# The nightly history pages (report/history) need the plots and the history database.
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/history/CMakeLists.txt AND TARGET report_html AND TARGET report_plots
   AND TARGET orchestrator_history)
  add_subdirectory(${CMAKE_CURRENT_LIST_DIR}/history ${CMAKE_CURRENT_BINARY_DIR}/history)
endif()
if(TARGET report_model AND TARGET report_html)
  if(TARGET report_plots AND TARGET report_images)
    add_library(report STATIC ${CMAKE_CURRENT_LIST_DIR}/html/standard_artwork.cc)
    target_link_libraries(report PUBLIC report_html PRIVATE report_plots report_images)
  else()
    add_library(report STATIC ${CMAKE_CURRENT_LIST_DIR}/html/no_artwork.cc)
    target_link_libraries(report PUBLIC report_html)
  endif()
  slamsweep_target_defaults(report)
  if(TARGET report_history)
    target_link_libraries(report PUBLIC report_history)
  endif()
  target_include_directories(report PUBLIC ${PROJECT_SOURCE_DIR})
endif()
