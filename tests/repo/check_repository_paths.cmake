# No tracked file names a path outside the repository (docs/DESIGN.md §2: the repository is
# self-contained; a reader of a clone must be able to follow every reference).
#
# Scans the text files `git ls-files` lists under SOURCE_DIR for
#   * relative paths (a token with a parent step, such as ..<slash>engines<slash>deck.yaml)
#     that, resolved from the file's own folder, leave the repository root, unless the part
#     after the leading parent steps names a tracked file or folder from some folder of the
#     repository (a deck snippet in a README whose path is relative to the deck's folder);
#   * absolute paths into machine-specific places: the folders work, root, home, tmp and
#     Users directly under the file-system root.
# URLs are removed before the scan; binary files (a NUL byte in the first 8000 bytes, git's
# rule) are skipped. A line that really needs such a path carries the marker
# `repository-paths: allow`.
#
# Variables: SOURCE_DIR (the repository root). Exit: 0 when every reference stays inside
# (also, with a message, when SOURCE_DIR is not the root of a git checkout or git is
# missing: a source tarball has nothing to scan), otherwise a fatal error listing
# file:line: token and why.
cmake_minimum_required(VERSION 3.22)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_repository_paths: SOURCE_DIR not set")
endif()
find_program(GIT_EXECUTABLE git)
if(NOT GIT_EXECUTABLE)
  message(STATUS "repository paths: skipped, git not found (nothing to scan without a checkout)")
  return()
endif()
execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --show-toplevel
  RESULT_VARIABLE rc OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
file(REAL_PATH "${SOURCE_DIR}" source_real)
if(rc EQUAL 0)
  file(REAL_PATH "${top}" top_real)
endif()
if(NOT rc EQUAL 0 OR NOT top_real STREQUAL source_real)
  message(STATUS "repository paths: skipped, ${SOURCE_DIR} is not the root of a git checkout")
  return()
endif()

execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" -c core.quotepath=off ls-files
  RESULT_VARIABLE rc OUTPUT_VARIABLE listing ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "repository paths: git ls-files failed: ${err}")
endif()
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" tracked "${listing}")
list(FILTER tracked EXCLUDE REGEX "^$")

# Every tracked file and every folder that holds one: what an in-repository path may name.
set(known "${tracked}")
foreach(f IN LISTS tracked)
  set(d "${f}")
  while(d MATCHES "/")
    string(REGEX REPLACE "/[^/]*$" "" d "${d}")
    list(APPEND known "${d}")
  endwhile()
endforeach()
list(REMOVE_DUPLICATES known)

# True when the text file `path` has a NUL byte in its first 8000 bytes.
function(is_binary path out)
  file(READ "${path}" hex HEX LIMIT 8000)
  set(from 0)
  set(result FALSE)
  while(TRUE)
    string(SUBSTRING "${hex}" ${from} -1 rest)
    string(FIND "${rest}" "00" pos)
    if(pos EQUAL -1)
      break()
    endif()
    math(EXPR at "${from} + ${pos}")
    math(EXPR odd "${at} % 2")
    if(odd EQUAL 0)
      set(result TRUE)
      break()
    endif()
    math(EXPR from "${at} + 1")
  endwhile()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The 1-based line of `path` that holds `token` (for the message only).
function(line_of path token out)
  file(READ "${path}" content)
  string(FIND "${content}" "${token}" pos)
  if(pos EQUAL -1)
    set(${out} "?" PARENT_SCOPE)
    return()
  endif()
  string(SUBSTRING "${content}" 0 ${pos} before)
  string(REGEX REPLACE "[^\n]" "" newlines "${before}")
  string(LENGTH "${newlines}" n)
  math(EXPR n "${n} + 1")
  set(${out} ${n} PARENT_SCOPE)
endfunction()

set(path_chars "-A-Za-z0-9_.~+@%=")  # dash first: a literal dash in a bracket
set(parent_step "[.][.]/")
set(url_regex "[A-Za-z][A-Za-z0-9+.-]*://[^] \t\"'<>()`]*")
set(absolute_regex "(^|[^${path_chars}/])(/(work|root|home|tmp|Users)/[^] \t\"'<>(),;`]*)")
set(relative_regex "[${path_chars}/]*${parent_step}[${path_chars}/]*")
set(allow_marker "repository-paths: allow")

set(problems "")
set(scanned 0)
foreach(f IN LISTS tracked)
  set(path "${SOURCE_DIR}/${f}")
  if(IS_SYMLINK "${path}" OR NOT EXISTS "${path}" OR IS_DIRECTORY "${path}")
    continue()
  endif()
  is_binary("${path}" binary)
  if(binary)
    continue()
  endif()
  math(EXPR scanned "${scanned} + 1")
  file(STRINGS "${path}" candidates ENCODING UTF-8
    REGEX "(${parent_step}|/(work|root|home|tmp|Users)/)")
  if(NOT candidates)
    continue()
  endif()
  cmake_path(GET f PARENT_PATH dir)
  foreach(line IN LISTS candidates)
    string(FIND "${line}" "${allow_marker}" allowed)
    if(NOT allowed EQUAL -1)
      continue()
    endif()
    string(REGEX REPLACE "${url_regex}" " " line "${line}")

    string(REGEX MATCHALL "${absolute_regex}" hits "${line}")
    foreach(hit IN LISTS hits)
      string(REGEX REPLACE "^[^/]" "" token "${hit}")
      line_of("${path}" "${token}" n)
      list(APPEND problems "${f}:${n}: ${token}: an absolute path into a machine-specific folder")
    endforeach()

    string(REGEX MATCHALL "${relative_regex}" hits "${line}")
    foreach(token IN LISTS hits)
      string(REGEX REPLACE "[.,]+$" "" token "${token}")
      if(token MATCHES "^/")
        continue()  # absolute: checked above
      endif()
      if(dir STREQUAL "")
        set(joined "${token}")
      else()
        set(joined "${dir}/${token}")
      endif()
      cmake_path(SET resolved NORMALIZE "${joined}")
      if(NOT resolved MATCHES "^[.][.](/|$)")
        continue()  # stays inside the repository
      endif()
      # Leaves the root from here. Allowed only if what follows the parent steps is a
      # tracked path seen from some folder of the repository.
      string(REGEX REPLACE "^([.]/)?(${parent_step})+" "" rest "${token}")
      cmake_path(SET rest NORMALIZE "${rest}")
      string(REGEX REPLACE "/$" "" rest "${rest}")
      set(names_something FALSE)
      if(NOT rest STREQUAL "" AND NOT rest MATCHES "^[.][.](/|$)")
        string(LENGTH "/${rest}" suffix_length)
        foreach(k IN LISTS known)
          string(LENGTH "${k}" k_length)
          if(k STREQUAL rest)
            set(names_something TRUE)
          elseif(k_length GREATER suffix_length)
            math(EXPR from "${k_length} - ${suffix_length}")
            string(SUBSTRING "${k}" ${from} -1 k_tail)
            if(k_tail STREQUAL "/${rest}")
              set(names_something TRUE)
            endif()
          endif()
          if(names_something)
            break()
          endif()
        endforeach()
      endif()
      if(NOT names_something)
        line_of("${path}" "${token}" n)
        list(APPEND problems
          "${f}:${n}: ${token}: resolves to ${resolved} from ${f}, outside the repository")
      endif()
    endforeach()
  endforeach()
endforeach()

if(problems)
  list(LENGTH problems count)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "repository paths: ${count} reference(s) outside the repository:\n  ${text}\n"
    "Name a file of the repository instead (or mark a line that really needs the path with "
    "`${allow_marker}`).")
endif()
message(STATUS "repository paths: ${scanned} tracked text files, every path stays inside the repository")
