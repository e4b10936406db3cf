# AUTOMOC with the project's include paths only.
#
# Given every include path, moc opens every header a moc'd file includes, Qt's and the
# standard library's among them: about 0.4 s per file on a quiet machine. The automoc
# steps took about 125 s of a 12.5-minute clean build, and a target's sources wait for
# its step. So AUTOMOC runs a wrapper (moc-own-includes.sh.in) that passes moc only
# the include paths inside the source and build trees: all the automoc steps then take
# 11 s, and the output is the same for all 160 files of ours (compared with the include
# line of the header normalised). Our own headers are still read, as they must be: moc
# registers a signal's argument type such as ViewportTool* (ToolManager.h) only when it
# has seen that class's Q_OBJECT.
#
# What moc no longer sees are Qt's classes: a signal or slot taking a pointer to a Qt
# QObject class (a QAction*, say) would not have its argument type registered for queued
# connections. None of ours does; should one need it, THRONG_MOC_INCLUDES=ON gives moc
# every include path again.
#
# throng_fast_moc(<dir>...): every target under <dir> with AUTOMOC on uses the wrapper.
option(THRONG_MOC_INCLUDES "Give AUTOMOC's moc every include path (slower)" OFF)

function(throng_collect_targets dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    throng_collect_targets("${sub}" more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(throng_fast_moc)
  if(THRONG_MOC_INCLUDES OR NOT TARGET Qt6::moc)
    return()
  endif()
  get_target_property(real_moc Qt6::moc IMPORTED_LOCATION)
  if(NOT real_moc)
    get_target_property(configs Qt6::moc IMPORTED_CONFIGURATIONS)
    list(GET configs 0 config)
    get_target_property(real_moc Qt6::moc IMPORTED_LOCATION_${config})
  endif()
  if(NOT real_moc OR NOT EXISTS "${real_moc}")
    return()
  endif()
  set(THRONG_REAL_MOC "${real_moc}")
  set(wrapper "${PROJECT_BINARY_DIR}/moc-own-includes.sh")
  configure_file("${PROJECT_SOURCE_DIR}/cmake/moc-own-includes.sh.in" "${wrapper}" @ONLY
                 FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
                                  WORLD_EXECUTE)
  foreach(dir IN LISTS ARGN)
    throng_collect_targets("${dir}" targets)
    foreach(target IN LISTS targets)
      get_target_property(automoc ${target} AUTOMOC)
      if(automoc)
        set_target_properties(${target} PROPERTIES AUTOMOC_EXECUTABLE "${wrapper}")
      endif()
    endforeach()
  endforeach()
endfunction()
