## ---------------------------------------------------------------------
## Run by `cmake --install` (install(SCRIPT) in install.cmake) after the
## documentation has been copied: the pages are written for the source tree,
## where README.md links to doc/..., doc/*.md to ../examples/...,
## ../include/... and ../tests/install_package/..., and the examples'
## READMEs to ../../doc/.... Installed,
##
##   P/share/doc/qsmpm/                doc/ and README.md
##   P/share/doc/qsmpm/user_model/     tests/install_package/ (the user model
##                                     of doc/user_models.md)
##   P/share/doc/qsmpm/umat/           tests/umat/ (the example UMATs)
##   P/share/qsmpm/examples/<name>/    examples/<name>/
##   P/include/                        include/
##
## so the relative links of the installed copies are rewritten here to the
## installed targets. The test installed_doc_links checks that every link
## of the installed pages resolves.
## ---------------------------------------------------------------------
set(_qsmpm_prefix "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}")
set(_qsmpm_doc "${_qsmpm_prefix}/share/doc/qsmpm")

file(GLOB _qsmpm_pages "${_qsmpm_doc}/*.md")
foreach(_page ${_qsmpm_pages})
  file(READ "${_page}" _text)
  get_filename_component(_name "${_page}" NAME)
  if(_name STREQUAL "README.md")
    # README.md sits next to the pages of doc/.
    string(REPLACE "](doc/" "](" _text "${_text}")
    string(REPLACE "](examples/" "](../../qsmpm/examples/" _text "${_text}")
    string(REPLACE "](include/" "](../../../include/" _text "${_text}")
  else()
    string(REPLACE "](../README.md" "](README.md" _text "${_text}")
    string(REPLACE "](../examples/" "](../../qsmpm/examples/" _text "${_text}")
    string(REPLACE "](../include/" "](../../../include/" _text "${_text}")
    string(REPLACE "](../tests/install_package/" "](user_model/" _text "${_text}")
    string(REPLACE "](../tests/umat" "](umat" _text "${_text}")
  endif()
  file(WRITE "${_page}" "${_text}")
endforeach()

file(GLOB _qsmpm_example_readmes "${_qsmpm_prefix}/share/qsmpm/examples/*/README.md")
foreach(_page ${_qsmpm_example_readmes})
  file(READ "${_page}" _text)
  string(REPLACE "](../../doc/" "](../../../doc/qsmpm/" _text "${_text}")
  string(REPLACE "](../../README.md" "](../../../doc/qsmpm/README.md" _text "${_text}")
  file(WRITE "${_page}" "${_text}")
endforeach()
