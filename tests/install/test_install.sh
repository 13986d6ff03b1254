#!/usr/bin/env bash
# `cmake --install` into a prefix under the build tree (issue 34): the program, the plot script,
# the man page (when help2man made one: HAVE_MAN=1) and the bash completion, each checked where a
# user meets it: `man -l` renders the page, and the completion, sourced into bash, completes a
# command, an option and an option's choices.
# usage: test_install.sh BUILD_DIR PREFIX HAVE_MAN
set -euo pipefail
build=$1 prefix=$2 have_man=$3
fail() { echo "test_install: $*" >&2; exit 1; }

rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
[ -x "$prefix/bin/mvpl" ] || fail "no bin/mvpl"
[ -f "$prefix/share/mvpl/plot_convergence.py" ] || fail "no share/mvpl/plot_convergence.py"
"$prefix/bin/mvpl" --version | grep -q '^mvpl [0-9]' || fail "bin/mvpl --version"

page="$prefix/share/man/man1/mvpl.1"
if [ "$have_man" = 1 ]; then
  [ -f "$page" ] || fail "no share/man/man1/mvpl.1"
  if command -v man >/dev/null; then
    text=$(MANPAGER=cat MANWIDTH=100 man -l "$page" 2>&1) || fail "man -l: $text"
    # The synopsis from `mvpl --help`, and a command's own options from `mvpl render --help`.
    grep -q 'mvpl COMMAND' <<<"$text" || fail "man page without the synopsis"
    grep -q -- '--time-budget' <<<"$text" || fail "man page without render's options"
  else
    echo "test_install: man is not installed; the page is not rendered"
  fi
fi

completion="$prefix/share/bash-completion/completions/mvpl"
[ -f "$completion" ] || fail "no share/bash-completion/completions/mvpl"
# COMPREPLY after _mvpl for the words of a command line, the last one being completed.
complete_words() {
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _mvpl; echo "${COMPREPLY[*]}"' \
    _ "$completion" "$@"
}
[ "$(complete_words mvpl ren)" = render ] || fail "'mvpl ren' completes to '$(complete_words mvpl ren)'"
[ "$(complete_words mvpl co)" = "compare convergence completion" ] ||
  fail "'mvpl co' completes to '$(complete_words mvpl co)'"
[ "$(complete_words mvpl render scene.gltf --time-b)" = --time-budget ] ||
  fail "'mvpl render --time-b' completes to '$(complete_words mvpl render scene.gltf --time-b)'"
[ "$(complete_words mvpl render scene.gltf --sampler '')" = "mc metropolis" ] ||
  fail "'mvpl render --sampler' completes to '$(complete_words mvpl render scene.gltf --sampler '')'"
echo "test_install: ok"
