# foldingmeshes_display_launcher(<out-var>)
#
# The command prefix for a test that renders: `xvfb-run -n <N> -a -s "<screen> -noreset"`, with
# a server number N of
# its own (B, B + 1, ... in the order the tests are added, where the base B = 200 + 50 k is
# chosen by a hash of the build directory, so that test runs of different build trees on one
# machine use different numbers), or nothing without xvfb-run.
# Plain `xvfb-run -a` starts every test at display 99, so rendering tests run back to back
# reuse one display number, and xvfb-run kills its Xvfb on exit without waiting for it: a
# server still shutting down can remove the socket of the next test's server on the same
# number ("bad X server connection"). Numbers of their own avoid that; -a still moves on to a
# free number if N is taken. The tests also hold RESOURCE_LOCK xvfb, so `ctest -j` never
# starts two X servers at one moment. (X servers of other programs on the machine, which
# xvfb-run only sees by their lock files, can still collide, but rarely; CI runs alone.)
# -noreset: without it Xvfb resets when its last client disconnects. pvpython/pvbatch connect
# once at start-up to probe OpenGL and disconnect; a busy machine can then see the first render
# window's XOpenDisplay land in the reset and abort ("bad X server connection", SIGABRT). On
# this machine with both cores loaded TestFoldingTreePV.py aborted 3 times in 4 without it,
# 0 in 8 with it.
find_program(FOLDINGMESHES_XVFB_RUN xvfb-run)
function(foldingmeshes_display_launcher out)
  if (NOT FOLDINGMESHES_XVFB_RUN)
    set(${out} "" PARENT_SCOPE)
    return ()
  endif ()
  get_property(number GLOBAL PROPERTY FOLDINGMESHES_NEXT_DISPLAY)
  if (NOT number)
    string(MD5 hash "${CMAKE_BINARY_DIR}")
    string(SUBSTRING "${hash}" 0 4 hash)
    math(EXPR number "200 + 50 * (0x${hash} % 80)")
  endif ()
  math(EXPR next "${number} + 1")
  set_property(GLOBAL PROPERTY FOLDINGMESHES_NEXT_DISPLAY ${next})
  set(${out} "${FOLDINGMESHES_XVFB_RUN};-n;${number};-a;-s;-screen 0 1280x1024x24 -noreset"
      PARENT_SCOPE)
endfunction()
