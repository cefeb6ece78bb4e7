#!/usr/bin/env bash
# make install's result: installs the build into a temporary prefix (cmake --install, as the
# Makefile's install target does), then runs the installed program from outside the checkout with
# a PATH and environment that know nothing of the build: `trapdem --help`, and `trapdem presets`
# finding its presets in PREFIX/share/trapdem/presets (a preset added only there must be listed);
# and, with the Python module built, `import trapdem` from PREFIX/lib/python3/dist-packages in a
# fresh Debian python3 that finds the installed presets too.
# Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
prefix=$(mktemp -d "${TMPDIR:-/tmp}/trapdem-install-XXXXXX")
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > "$prefix.log" 2>&1 || { cat "$prefix.log"; rm -f "$prefix.log"; exit 1; }
rm -f "$prefix.log"
test -x "$prefix/bin/trapdem" || { echo "no $prefix/bin/trapdem after install"; exit 1; }
test -f "$prefix/share/trapdem/presets/tiny.toml" || { echo "no presets in $prefix/share/trapdem/presets"; exit 1; }
sed 's/^name = "tiny"/name = "only-installed"/' "$prefix/share/trapdem/presets/tiny.toml" \
  > "$prefix/share/trapdem/presets/only-installed.toml"
cd "$prefix"
unset TRAPDEM_PRESETS
export PATH="$prefix/bin:/usr/bin:/bin"
help=$(trapdem --help)
grep -q "run" <<< "$help" || { echo "trapdem --help: unexpected output"; echo "$help"; exit 1; }
presets=$(trapdem presets)
grep -q "^only-installed " <<< "$presets" || { echo "trapdem presets does not read $prefix/share/trapdem/presets:"; echo "$presets"; exit 1; }
grep -q "^tiny " <<< "$presets" || { echo "trapdem presets: no tiny"; echo "$presets"; exit 1; }
if [ -f "$build/python/trapdem/__init__.py" ]; then
  site="$prefix/lib/python3/dist-packages"
  test -f "$site/trapdem/__init__.py" || { echo "no $site/trapdem after install"; exit 1; }
  names=$(env -i PATH=/usr/bin:/bin PYTHONPATH="$site" /usr/bin/python3 -c \
    'import trapdem; print(trapdem.__file__); print(" ".join(trapdem.presets()))')
  grep -q "^$site/trapdem/__init__.py$" <<< "$names" || { echo "import trapdem did not take the installed package:"; echo "$names"; exit 1; }
  grep -qw "only-installed" <<< "$names" || { echo "trapdem.presets() does not read $prefix/share/trapdem/presets:"; echo "$names"; exit 1; }
fi
echo "installed in $prefix: trapdem --help and trapdem presets work from there (and import trapdem, when built)"
