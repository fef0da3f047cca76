# FreeImage ships no CMake package on Debian; vcpkg provides one (freeimage::FreeImage).
# This module finds either and exposes the imported target FreeImage::FreeImage.
find_package(freeimage CONFIG QUIET)
if(TARGET freeimage::FreeImage)
    if(NOT TARGET FreeImage::FreeImage)
        add_library(FreeImage::FreeImage INTERFACE IMPORTED)
        target_link_libraries(FreeImage::FreeImage INTERFACE freeimage::FreeImage)
    endif()
    set(FreeImage_FOUND TRUE)
    return()
endif()

find_path(FreeImage_INCLUDE_DIR FreeImage.h)
find_library(FreeImage_LIBRARY NAMES freeimage FreeImage)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FreeImage REQUIRED_VARS FreeImage_LIBRARY FreeImage_INCLUDE_DIR)
if(FreeImage_FOUND AND NOT TARGET FreeImage::FreeImage)
    add_library(FreeImage::FreeImage UNKNOWN IMPORTED)
    set_target_properties(FreeImage::FreeImage PROPERTIES
        IMPORTED_LOCATION "${FreeImage_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${FreeImage_INCLUDE_DIR}")
endif()
