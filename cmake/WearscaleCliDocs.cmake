# The CLI's man page (help2man, from `wearscale --help-all` and
# apps/wearscale/wearscale.h2m) and its bash and zsh completion scripts
# (`wearscale completion bash|zsh`), made at build time from the program
# itself so that they list every command, flag and choice it has; installed
# by `cmake --install` into share/man/man1, share/bash-completion/completions
# and share/zsh/site-functions. Without help2man the man page is skipped with
# a message; the completions need nothing but the program.
include(GNUInstallDirs)
find_program(WEARSCALE_HELP2MAN help2man)

set(cli_docs ${PROJECT_BINARY_DIR}/cli-docs)
set(bash_completion ${cli_docs}/bash-completion/wearscale)
set(zsh_completion ${cli_docs}/zsh/_wearscale)
set(man_page ${cli_docs}/man1/wearscale.1)
# Every command's help, which tests/apps/test_help_examples_cli.cpp reads its examples from.
set(WEARSCALE_HELP_ALL ${cli_docs}/help-all.txt)
set(h2m ${PROJECT_SOURCE_DIR}/apps/wearscale/wearscale.h2m)

add_custom_command(OUTPUT ${bash_completion} ${zsh_completion} ${WEARSCALE_HELP_ALL}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${cli_docs}/bash-completion ${cli_docs}/zsh
  COMMAND $<TARGET_FILE:wearscale> completion bash > ${bash_completion}
  COMMAND $<TARGET_FILE:wearscale> completion zsh > ${zsh_completion}
  COMMAND $<TARGET_FILE:wearscale> --help-all > ${WEARSCALE_HELP_ALL}
  DEPENDS wearscale VERBATIM COMMENT "Generating the bash and zsh completion of wearscale")
set(outputs ${bash_completion} ${zsh_completion})

# help2man reads the help in its own locale, C unless told: every byte of µ, ν,
# ≥, §, … became '?' in the page. It reads it as UTF-8 here, and preconv (groff)
# turns each of those characters into its groff escape \[uXXXX]: an ASCII page
# that man renders as the character in a UTF-8 locale and as groff's ASCII
# fallback (<nu>, >=) in the C locale, whatever encoding man assumes. Without
# preconv the page stays UTF-8 (man-db reads that too). The --help text is
# untouched.
find_program(WEARSCALE_PRECONV preconv)
if(WEARSCALE_HELP2MAN)
  set(man_source ${man_page})
  if(WEARSCALE_PRECONV)
    set(man_source ${cli_docs}/wearscale.1.utf8)
  endif()
  set(man_commands
    COMMAND ${CMAKE_COMMAND} -E make_directory ${cli_docs}/man1
    COMMAND ${CMAKE_COMMAND} -E env CI=true ${WEARSCALE_HELP2MAN} --no-info --no-discard-stderr --locale=C.UTF-8
            --help-option=--help-all --version-option=--version --include=${h2m}
            --output=${man_source} $<TARGET_FILE:wearscale>)
  if(WEARSCALE_PRECONV)
    list(APPEND man_commands COMMAND ${WEARSCALE_PRECONV} -r -e UTF-8 ${man_source} > ${man_page})
  endif()
  add_custom_command(OUTPUT ${man_page} ${man_commands}
    DEPENDS wearscale ${h2m} VERBATIM COMMENT "Generating the wearscale(1) man page (help2man)")
  list(APPEND outputs ${man_page})
  install(FILES ${man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "wearscale: help2man not found, no man page (apt install help2man)")
endif()
add_custom_target(wearscale_cli_docs ALL DEPENDS ${outputs})

install(FILES ${bash_completion} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES ${zsh_completion} DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/site-functions)
