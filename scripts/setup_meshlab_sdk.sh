#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets up what the MeshLab 2020.09 plugin needs on Debian bookworm. Idempotent.
#
#  1. installs the missing Debian packages (meshlab, Qt5, Eigen, GLEW, OpenMesh, Xvfb, dpkg-dev);
#  2. adds a `deb-src` entry for bookworm if apt has none (deb822 `.sources` or one-line `.list`);
#  3. fetches MeshLab's Debian source (`apt-get source meshlab`) into third_party/meshlab-sdk/
#     (git-ignored; no MeshLab code enters the repo), unless it is already there.
#
# Prints the SDK dir (the folder holding src/common/interfaces.h and vcglib/) as its last line,
# so `cmake -DMESHLAB_SDK_DIR="$(scripts/setup_meshlab_sdk.sh | tail -n1)"` works.
#
# Usage: scripts/setup_meshlab_sdk.sh [--sdk-root DIR]
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sdk_root="${repo_root}/third_party/meshlab-sdk"
if [ "${1:-}" = "--sdk-root" ]; then
  sdk_root="$2"
fi

log() { echo "setup_meshlab_sdk: $*" >&2; }

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then
    sudo_cmd=(sudo)
  else
    sudo_cmd=(false)  # only fails if something actually has to be installed
  fi
fi
as_root() {
  if [ "${sudo_cmd[0]:-}" = "false" ]; then
    log "need root or sudo to run: $*"
    exit 1
  fi
  "${sudo_cmd[@]}" "$@"
}

export DEBIAN_FRONTEND=noninteractive
apt_update() {
  as_root apt-get update -qq
}

# --- 1. Debian packages ----------------------------------------------------------------------
packages=(meshlab qtbase5-dev libqt5opengl5-dev libeigen3-dev libglew-dev libopenmesh-dev
          xvfb xauth dpkg-dev xz-utils
          xdotool x11-utils imagemagick)  # the real-GUI tests (tests/meshlab/gui_detect.sh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing ${missing[*]}"
  apt_update
  as_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# --- 2. a deb-src entry ----------------------------------------------------------------------
# Lists every apt source file (one-line .list and deb822 .sources).
source_files() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && echo "$f"
  done
}

# True if an enabled deb-src entry exists (for any suite: bookworm-updates alone is not enough,
# so require the plain suite name of the release).
has_deb_src() {
  local f
  while read -r f; do
    case "$f" in
      *.sources)
        # deb822: paragraphs separated by blank lines; need Types containing deb-src, Suites
        # containing the release and not Enabled: no.
        awk -v suite="$codename" '
          function flush() {
            if (types ~ /(^|[ \t])deb-src([ \t]|$)/ && (" " suites " ") ~ (" " suite " ") && enabled != "no") found = 1
            types = ""; suites = ""; enabled = ""
          }
          /^[ \t]*$/ { flush(); next }
          /^[ \t]*#/ { next }
          tolower($1) == "types:"   { $1 = ""; types = $0 }
          tolower($1) == "suites:"  { $1 = ""; suites = $0; gsub(/[ \t]+/, " ", suites) }
          tolower($1) == "enabled:" { enabled = tolower($2) }
          END { flush(); exit found ? 0 : 1 }' "$f" && return 0
        ;;
      *)
        grep -Eq "^[[:space:]]*deb-src[[:space:]]+(\[[^]]*\][[:space:]]+)?[^[:space:]]+[[:space:]]+${codename}[[:space:]]" "$f" && return 0
        ;;
    esac
  done < <(source_files)
  return 1
}

# The archive URI that serves the release's binary packages (reuse the mirror apt already uses).
release_uri() {
  local f uri=""
  while read -r f; do
    case "$f" in
      *.sources)
        uri=$(awk -v suite="$codename" '
          function flush() {
            if (!done && types ~ /(^|[ \t])deb([ \t]|$)/ && (" " suites " ") ~ (" " suite " ") && enabled != "no" && uris != "") { print uris; done = 1 }
            types = ""; suites = ""; enabled = ""; uris = ""
          }
          /^[ \t]*$/ { flush(); next }
          /^[ \t]*#/ { next }
          tolower($1) == "types:"   { $1 = ""; types = $0 }
          tolower($1) == "uris:"    { uris = $2 }
          tolower($1) == "suites:"  { $1 = ""; suites = $0; gsub(/[ \t]+/, " ", suites) }
          tolower($1) == "enabled:" { enabled = tolower($2) }
          END { flush() }' "$f" | head -n1)
        ;;
      *)
        uri=$(sed -nE "s/^[[:space:]]*deb[[:space:]]+(\[[^]]*\][[:space:]]+)?([^[:space:]]+)[[:space:]]+${codename}[[:space:]].*/\2/p" "$f" | head -n1)
        ;;
    esac
    if [ -n "$uri" ]; then
      echo "$uri"
      return 0
    fi
  done < <(source_files)
  echo "http://deb.debian.org/debian"
}

codename=$( . /etc/os-release && echo "${VERSION_CODENAME:-bookworm}" )
if ! has_deb_src; then
  uri=$(release_uri)
  if ls /etc/apt/sources.list.d/*.sources >/dev/null 2>&1 || [ ! -s /etc/apt/sources.list ]; then
    target=/etc/apt/sources.list.d/meshbridge-deb-src.sources
    log "adding deb-src ${uri} ${codename} main in ${target}"
    keyring=/usr/share/keyrings/debian-archive-keyring.gpg
    {
      echo "# Added by MeshBridge scripts/setup_meshlab_sdk.sh (MeshLab plugin headers)"
      echo "Types: deb-src"
      echo "URIs: ${uri}"
      echo "Suites: ${codename}"
      echo "Components: main"
      [ -f "$keyring" ] && echo "Signed-By: ${keyring}"
    } | as_root tee "$target" >/dev/null
  else
    target=/etc/apt/sources.list.d/meshbridge-deb-src.list
    log "adding deb-src ${uri} ${codename} main in ${target}"
    echo "deb-src ${uri} ${codename} main" | as_root tee "$target" >/dev/null
  fi
  apt_update
elif ! apt-cache showsrc meshlab >/dev/null 2>&1 || [ -z "$(apt-cache showsrc meshlab 2>/dev/null)" ]; then
  apt_update  # entry present but its index was never fetched
fi

# --- 3. MeshLab source -----------------------------------------------------------------------
# The SDK dir is the folder that holds src/common/interfaces.h and vcglib/.
find_sdk() {
  local hdr
  hdr=$(find "$sdk_root" -maxdepth 5 -path '*/src/common/interfaces.h' 2>/dev/null | sort | head -n1)
  [ -n "$hdr" ] || return 1
  local dir
  dir=$(dirname "$(dirname "$(dirname "$hdr")")")
  [ -d "$dir/vcglib/vcg" ] || [ -d "$dir/src/vcglib/vcg" ] || return 1
  echo "$dir"
}

if sdk_dir=$(find_sdk); then
  log "MeshLab source already present"
else
  mkdir -p "$sdk_root"
  cd "$sdk_root"
  # apt-get source as root warns that it downloads unsandboxed; that is harmless here.
  if command -v dpkg-source >/dev/null; then
    log "apt-get source meshlab (into ${sdk_root})"
    apt-get source -qq meshlab >/dev/null 2>"${sdk_root}/apt-get-source.log" \
      || { cat "${sdk_root}/apt-get-source.log" >&2; exit 1; }
  else
    log "apt-get source --download-only meshlab (no dpkg-source: untarring the .orig.tar.xz)"
    apt-get source -qq --download-only meshlab >/dev/null 2>"${sdk_root}/apt-get-source.log" \
      || { cat "${sdk_root}/apt-get-source.log" >&2; exit 1; }
    tar -xf meshlab_*.orig.tar.*
  fi
  sdk_dir=$(find_sdk) || { log "no src/common/interfaces.h + vcglib/ under ${sdk_root}"; exit 1; }
fi

# Debian's package puts vcglib under src/vcglib in some versions; the plugin wants <sdk>/vcglib.
if [ ! -e "$sdk_dir/vcglib" ] && [ -d "$sdk_dir/src/vcglib" ]; then
  ln -s src/vcglib "$sdk_dir/vcglib"
fi
echo "$sdk_dir"
