# contensou_install_module(<component> <targets...>): installs a module's libraries and exports
# them as contensou-<component>-targets.cmake, a component of the package config.
function(contensou_install_module component)
  install(TARGETS ${ARGN} EXPORT contensou-${component}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT contensou-${component}-targets NAMESPACE contensou::
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/contensou)
endfunction()

# contensou_find_module_dependencies(<module> <package>...): for a build of the Python package
# alone, where identification and gear are optional. Looks for each package quietly and sets
# CONTENSOU_HAVE_<module> (all found) and CONTENSOU_<module>_MISSING, the packages not found with
# their Debian names ("Ceres (Debian: libceres-dev)"), which the package's ImportError shows.
set(_contensou_debian_Ceres libceres-dev)
set(_contensou_debian_Boost libboost-dev)
set(_contensou_debian_nlohmann_json nlohmann-json3-dev)
set(_contensou_debian_SUNDIALS libsundials-dev)
set(_contensou_debian_Threads libc6-dev)
function(contensou_find_module_dependencies module)
  set(missing "")
  foreach(package IN LISTS ARGN)
    find_package(${package} QUIET)
    if(NOT ${package}_FOUND)
      list(APPEND missing "${package} (Debian: ${_contensou_debian_${package}})")
    endif()
  endforeach()
  if(missing)
    set(CONTENSOU_HAVE_${module} FALSE PARENT_SCOPE)
    list(JOIN missing ", " text)
    message(STATUS "contensou: no ${module} module in the Python package: ${text} not found")
  else()
    set(CONTENSOU_HAVE_${module} TRUE PARENT_SCOPE)
  endif()
  set(CONTENSOU_${module}_MISSING "${missing}" PARENT_SCOPE)
endfunction()
