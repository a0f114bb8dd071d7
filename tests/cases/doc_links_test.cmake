# cases/scripts/check_doc_links.py: every relative link and #anchor of the tracked Markdown files
# resolves. On the source tree (a git checkout) it must pass; on a small repository made here with
# one broken anchor and one missing file it must fail, naming both.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DSOURCE=... -DWORK=...
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${SOURCE}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "check_doc_links.py on the source tree: exit ${code}\n${out}${err}")
endif()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/docs")
file(WRITE "${WORK}/README.md" "# Top\n\n## A section\n\nSee [the guide](docs/guide.md#usage), "
                               "[a section](#a-section) and [gone](docs/gone.md).\n")
file(WRITE "${WORK}/docs/guide.md" "# Guide\n\n## Use\n\nBack to [the top](../README.md#top).\n")
execute_process(COMMAND git init -q "${WORK}" RESULT_VARIABLE code)
execute_process(COMMAND git -C "${WORK}" add README.md docs/guide.md RESULT_VARIABLE added)
if(NOT code EQUAL 0 OR NOT added EQUAL 0)
    message(FATAL_ERROR "could not make the test repository in ${WORK}")
endif()
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 1 OR NOT out MATCHES "README.md:5: docs/guide.md#usage"
   OR NOT out MATCHES "README.md:5: docs/gone.md" OR out MATCHES "#a-section|#top")
    message(FATAL_ERROR "check_doc_links.py on a broken tree: exit ${code}, wanted 1 naming "
                        "docs/guide.md#usage and docs/gone.md only\n${out}${err}")
endif()
