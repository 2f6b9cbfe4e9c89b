// SPDX-License-Identifier: GPL-3.0-or-later
//! \file meshlab_abi_probe.cpp
//! Configure-time probe (try_run from MeshLabSDK.cmake): loads one of the installed MeshLab's
//! own plugins (MeshLab >= 2022) and prints the MESHLAB_VERSION and MESHLAB_SCALAR it was
//! compiled with, as "<version>;<float|double>". MeshLab's PluginManager refuses a plugin whose
//! version differs in its first six characters or whose precision differs, so ours must be
//! built with exactly these. Needs no MESHLAB_* define itself: MeshLabPlugin's layout does not
//! depend on them, and getMLVersion() runs the loaded plugin's code.

#include <common/plugins/interfaces/meshlab_plugin.h>

#include <QPluginLoader>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: meshlab_abi_probe <MeshLab plugin .so>\n");
    return 2;
  }
  QPluginLoader loader(QString::fromLocal8Bit(argv[1]));
  QObject* instance = loader.instance();
  if (instance == nullptr) {
    std::fprintf(stderr, "cannot load %s: %s\n", argv[1], qPrintable(loader.errorString()));
    return 1;
  }
  const MeshLabPlugin* plugin = dynamic_cast<const MeshLabPlugin*>(instance);
  if (plugin == nullptr) {
    std::fprintf(stderr, "%s is not a MeshLab >= 2022 plugin\n", argv[1]);
    return 1;
  }
  const std::pair<std::string, bool> version = plugin->getMLVersion();
  std::printf("%s;%s", version.first.c_str(), version.second ? "double" : "float");
  return 0;
}
