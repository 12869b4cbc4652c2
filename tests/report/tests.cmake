# Tests of the report (model, pages, WriteReport, browser). tests/report/plots_images belongs to
# the plots/images suite.
if(TARGET report_html)
  add_library(report_test_fixture STATIC fixture_sweep.cc fake_artwork.cc)
  slamsweep_target_defaults(report_test_fixture)
  target_include_directories(report_test_fixture PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(report_test_fixture
    PUBLIC report_html evaluator_core nlohmann_json::nlohmann_json
    PRIVATE evaluator_map_formats evaluator_trajectory_formats opencv_core opencv_imgproc opencv_imgcodecs fmt::fmt)

  slamsweep_add_test(report_model_test SOURCES model_test.cc best_marks_test.cc significance_test.cc published_rows_test.cc LIBS report_model orchestrator_store
                     report_test_fixture)
  # The shipped configs/published.yaml is read by a test too.
  target_compile_definitions(report_model_test PRIVATE SLAMSWEEP_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  slamsweep_add_test(report_html_test SOURCES html_test.cc LIBS report_html)
  slamsweep_add_test(report_write_test SOURCES write_report_test.cc LIBS report_html report_test_fixture)
  # The segment-length and parameter pages: their models, figures as planned, pages.
  slamsweep_add_test(report_views_test SOURCES views_model_test.cc view_pages_test.cc
                     LIBS report_html report_test_fixture)
endif()
if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/plots_images/CMakeLists.txt)
  add_subdirectory(plots_images)
endif()

# "Maps compared" on the sequence pages: planning with the fake image maker, and real panels.
if(TARGET report)
  slamsweep_add_test(report_maps_test SOURCES maps_compared_test.cc LIBS report report_test_fixture opencv_core opencv_imgcodecs)
endif()

# Headless Chromium against a local server sending Jenkins' CSP (skipped without chromium, failing under CI).
# Its screenshots are kept in build/artefacts/report-screenshots/ for a person (or CI) to look at.
if(TARGET report)
  slamsweep_add_test(report_browser_test SOURCES browser_test.cc LIBS report report_test_fixture)
  target_compile_definitions(report_browser_test PRIVATE
    SLAMSWEEP_CSP_SERVER="${CMAKE_CURRENT_SOURCE_DIR}/csp_server.py"
    SLAMSWEEP_ARTIFACT_DIR="${CMAKE_BINARY_DIR}/artefacts/report-screenshots")
endif()

# `slamsweep report` through its registration function (cli/report_command.cc compiled here,
# since the command is wired into slamsweep_cli by the lead).
if(TARGET report)
  slamsweep_add_test(report_command_test SOURCES report_command_test.cc ${PROJECT_SOURCE_DIR}/cli/report_command.cc
                     LIBS report report_test_fixture CLI11::CLI11)
endif()

# Nightly history pages (report/history) against synthetic sweeps and a history database.
if(TARGET report_history AND TARGET report_test_fixture AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/history/CMakeLists.txt)
  add_subdirectory(history)
endif()
