# fas_keep_MPI_off_X_displays(): every test of the calling directory runs with hwloc's OpenGL
# plugin off (HWLOC_COMPONENTS=-gl).
#
# Every pvbatch and mpiexec starts Open MPI, whose daemon loads hwloc's plugins; the OpenGL one
# opens each X display :0 to :9 in turn to look for GPUs (measured: 57 connections per pvbatch
# start).  When one of those displays is the private Xvfb of another test that is stopping at that
# moment, Xlib ends the daemon ("XIO: fatal IO error 11 ... on X server") and MPI_Init fails
# ("Unable to start a daemon on the local node"): a test fails for a reason of its neighbour's.
# Without the plugin no process touches a display it was not given.
function(fas_keep_MPI_off_X_displays)
  get_directory_property(tests TESTS)
  if(tests)
    set_property(TEST ${tests} APPEND PROPERTY ENVIRONMENT "HWLOC_COMPONENTS=-gl")
  endif()
endfunction()
