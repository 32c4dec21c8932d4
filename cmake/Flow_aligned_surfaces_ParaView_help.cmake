# Whether the ParaView plugin can carry its help pages (the "?" button): sets FAS_PARAVIEW_HELP,
# which paraview_add_plugin's XML_DOCUMENTATION takes.  ParaView's paraview_client_documentation()
# runs xmlpatterns over the filters' XML and paraview_client_generate_help() runs Qt's
# qhelpgenerator (found through Qt's Help CMake package); both stop the configuration with a bare
# "cannot find" when they are missing, so they are looked for here first, and a machine without
# them builds the plugin without its help instead.
set(fas_help_missing "")
if(NOT PARAVIEW_USE_QT)
  # A ParaView without its Qt GUI has no help window: nothing to build, nothing missing.
  set(FAS_PARAVIEW_HELP OFF)
  message(STATUS "ParaView has no Qt GUI: the plugin's help pages are not built")
  return()
endif()

# Debian's /usr/bin/xmlpatterns is qtchooser's, installed whether or not the tool is (it then
# fails when run): the tool counts as found when it runs.  qtchooser runs the real one from
# /usr/lib/qt5/bin, looked in first.
find_program(FAS_XMLPATTERNS NAMES xmlpatterns-qt5 xmlpatterns HINTS /usr/lib/qt5/bin
  DOC "xmlpatterns, which turns the ParaView plugin's XML into its help pages")
set(fas_xmlpatterns_runs FALSE)
if(FAS_XMLPATTERNS)
  execute_process(COMMAND "${FAS_XMLPATTERNS}" -version
    RESULT_VARIABLE fas_xmlpatterns_result OUTPUT_QUIET ERROR_QUIET)
  if(fas_xmlpatterns_result EQUAL 0)
    set(fas_xmlpatterns_runs TRUE)
  endif()
endif()
if(fas_xmlpatterns_runs)
  # ParaView's own search would take the first xmlpatterns on the PATH; it takes this one.
  if(NOT qt_xmlpatterns_executable)
    set(qt_xmlpatterns_executable "${FAS_XMLPATTERNS}" CACHE FILEPATH "Path to xmlpatterns" FORCE)
  endif()
else()
  list(APPEND fas_help_missing "xmlpatterns (qtxmlpatterns5-dev-tools)")
endif()

# Qt's Help package defines Qt5::qhelpgenerator; on Debian, qttools5-dev brings the package and,
# through its dependency on qttools5-dev-tools, the program.
find_package(Qt5 QUIET COMPONENTS Help)
if(NOT Qt5Help_FOUND OR NOT TARGET Qt5::qhelpgenerator)
  list(APPEND fas_help_missing "Qt5's Help CMake package and qhelpgenerator (qttools5-dev, qttools5-dev-tools)")
endif()

if(fas_help_missing)
  set(FAS_PARAVIEW_HELP OFF)
  string(JOIN ", " fas_help_missing ${fas_help_missing})
  if(FAS_REQUIRE_ALL_TOOLS)
    message(FATAL_ERROR "FAS_REQUIRE_ALL_TOOLS (CI=true): missing ${fas_help_missing}: the ParaView "
                        "plugin's help pages (its \"?\" button) would not be built nor tested; "
                        "scripts/install-deps.sh installs them")
  endif()
  message(STATUS "The ParaView plugin is built without its help pages (the \"?\" button shows a "
                 "generic page): missing ${fas_help_missing}; scripts/install-deps.sh installs them")
else()
  set(FAS_PARAVIEW_HELP ON)
  message(STATUS "Qt's help tools found: the ParaView plugin carries its help pages")
endif()
