# SPDX-License-Identifier: MIT
# What `cmake --install` puts beside the programs (app/CMakeLists.txt installs those), and the
# Debian package CPack makes of it (scripts/package.sh, docs/PACKAGING.md): the desktop file, the
# MIME type of run files, icons, AppStream metadata, the manual page, copyright and changelog.
# tests/package/check_package.sh checks the package.

set(BRIDGESCOPE_APP_ID io.github.bridgescope.Bridgescope) # the desktop file's and AppStream's id
set(packaging_src ${PROJECT_SOURCE_DIR}/resources/packaging)
set(packaging_out ${PROJECT_BINARY_DIR}/packaging)
set(BRIDGESCOPE_DOCDIR ${CMAKE_INSTALL_DATADIR}/doc/bridgescope)

# The changelog's latest entry is this version's; its date is the release date that AppStream
# and the manual page show.
file(STRINGS ${packaging_src}/changelog changelog_lines)
list(GET changelog_lines 0 changelog_head)
if(NOT changelog_head MATCHES "^bridgescope \\(${PROJECT_VERSION}\\) ")
    message(WARNING "resources/packaging/changelog: the latest entry is not version ${PROJECT_VERSION} "
                    "(${changelog_head}); add an entry for it")
endif()
set(BRIDGESCOPE_RELEASE_DATE "")
foreach(line IN LISTS changelog_lines)
    if(line MATCHES "^ -- .*>  [A-Z][a-z][a-z], ([0-9]+) ([A-Z][a-z][a-z]) ([0-9][0-9][0-9][0-9]) ")
        set(months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
        list(FIND months "${CMAKE_MATCH_2}" month)
        math(EXPR month "${month} + 1" OUTPUT_FORMAT DECIMAL)
        string(LENGTH "${month}" n)
        if(n EQUAL 1)
            set(month "0${month}")
        endif()
        set(day "${CMAKE_MATCH_1}")
        string(LENGTH "${day}" n)
        if(n EQUAL 1)
            set(day "0${day}")
        endif()
        set(BRIDGESCOPE_RELEASE_DATE "${CMAKE_MATCH_3}-${month}-${day}")
        break()
    endif()
endforeach()
if(NOT BRIDGESCOPE_RELEASE_DATE)
    message(FATAL_ERROR "resources/packaging/changelog: no trailer line ( -- NAME <MAIL>  DATE) found")
endif()

configure_file(${packaging_src}/${BRIDGESCOPE_APP_ID}.metainfo.xml
               ${packaging_out}/${BRIDGESCOPE_APP_ID}.metainfo.xml @ONLY)
configure_file(${packaging_src}/bridgescope.1.in ${packaging_out}/bridgescope.1 @ONLY)
configure_file(${packaging_src}/changelog ${packaging_out}/changelog COPYONLY)

# The copyright file in Debian's machine-readable format, with LICENSE's text (MIT is "Expat"
# there).
file(STRINGS ${PROJECT_SOURCE_DIR}/LICENSE license_lines)
list(FILTER license_lines EXCLUDE REGEX "^MIT License$")
set(copyright_line "")
set(license_text "")
foreach(line IN LISTS license_lines)
    if(line MATCHES "^Copyright \\(c\\) (.*)$")
        set(copyright_line "${CMAKE_MATCH_1}")
    elseif(line STREQUAL "" AND license_text STREQUAL "")
    elseif(line STREQUAL "")
        string(APPEND license_text " .\n")
    else()
        string(APPEND license_text " ${line}\n")
    endif()
endforeach()
file(WRITE ${packaging_out}/copyright.new
     "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
     "Upstream-Name: Bridgescope\n\n"
     "Files: *\n"
     "Copyright: ${copyright_line}\n"
     "License: Expat\n"
     "${license_text}")
configure_file(${packaging_out}/copyright.new ${packaging_out}/copyright COPYONLY)

# Debian wants manual pages and changelogs compressed, without a time stamp (gzip -n).
find_program(GZIP_PROGRAM gzip REQUIRED)
add_custom_command(OUTPUT ${packaging_out}/bridgescope.1.gz
    COMMAND ${GZIP_PROGRAM} -9 -n -k -f ${packaging_out}/bridgescope.1
    DEPENDS ${packaging_out}/bridgescope.1 VERBATIM)
add_custom_command(OUTPUT ${packaging_out}/changelog.gz
    COMMAND ${GZIP_PROGRAM} -9 -n -k -f ${packaging_out}/changelog
    DEPENDS ${packaging_out}/changelog VERBATIM)
set(packaging_files ${packaging_out}/bridgescope.1.gz ${packaging_out}/changelog.gz)

# Icons for the desktop's hicolor theme: the SVG and PNGs rendered from it.
set(icon_svg ${PROJECT_SOURCE_DIR}/resources/icons/bridgescope.svg)
set(BRIDGESCOPE_ICON_SIZES 16 32 48 64 128 256)
find_program(RSVG_CONVERT rsvg-convert)
if(RSVG_CONVERT)
    foreach(size IN LISTS BRIDGESCOPE_ICON_SIZES)
        set(png ${packaging_out}/icons/${size}x${size}/bridgescope.png)
        add_custom_command(OUTPUT ${png}
            COMMAND ${CMAKE_COMMAND} -E make_directory ${packaging_out}/icons/${size}x${size}
            COMMAND ${RSVG_CONVERT} --width ${size} --height ${size} --output ${png} ${icon_svg}
            DEPENDS ${icon_svg} VERBATIM)
        list(APPEND packaging_files ${png})
        install(FILES ${png} DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
    endforeach()
else()
    message(WARNING "rsvg-convert (Debian: librsvg2-bin) not found: installs only the SVG icon, "
                    "without the PNG sizes (scripts/setup.sh installs it)")
endif()
add_custom_target(bridgescope_packaging_files ALL DEPENDS ${packaging_files})

install(FILES ${PROJECT_SOURCE_DIR}/resources/${BRIDGESCOPE_APP_ID}.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${packaging_src}/bridgescope-mime.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME bridgescope.xml)
install(FILES ${packaging_out}/${BRIDGESCOPE_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES ${icon_svg} DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${packaging_out}/bridgescope.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
# The Prometheus rules for `watch --metrics` (`bridgescope rules` prints the same file), and the
# example configurations of a fleet (docs/fleet.md): a lab's scrapes, a vehicle's agent, federation.
install(FILES ${PROJECT_SOURCE_DIR}/resources/prometheus/bridgescope-rules.yml
              ${PROJECT_SOURCE_DIR}/resources/prometheus/prometheus.yml
              ${PROJECT_SOURCE_DIR}/resources/prometheus/agent.yml
              ${PROJECT_SOURCE_DIR}/resources/prometheus/federation.yml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bridgescope/prometheus)
# A native package (no Debian revision): its changelog is changelog.gz.
install(FILES ${packaging_out}/copyright ${packaging_out}/changelog.gz DESTINATION ${BRIDGESCOPE_DOCDIR})

# The Debian package: bridgescope_VERSION_ARCH.deb.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME bridgescope)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Bridgescope developers")
set(CPACK_PACKAGE_CONTACT "Bridgescope developers <bridgescope@example.org>")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "discover, bridge and measure ROS-MQTT links")
set(CPACK_PACKAGE_DESCRIPTION
    "Bridgescope is a Qt desktop tool for people who connect ROS robots and vehicles
over MQTT with the mqtt_client bridge. It discovers the ROS 1 graph and the
MQTT broker's topic tree side by side; edits, validates and converts
mqtt_client configs, built by dragging ROS topics onto MQTT and back; and
measures the link: per-stage latency distributions from timestamp topics,
recorded runs, reports (Markdown, LaTeX, HTML, PDF), links watched for hours
with Prometheus metrics, and unattended experiment matrices.

Its demo lab (bridgescope --demo) needs mosquitto and rosmaster, which this
package recommends.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Libraries from dpkg-shlibdeps; Qt's SQLite driver is a plugin (run files), not linked.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6sql6-sqlite")
# The demo lab starts mosquitto and rosmaster (python3-rosmaster; ros-core has it and more).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mosquitto, python3-rosmaster")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "ros-core, mosquitto-clients, qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
