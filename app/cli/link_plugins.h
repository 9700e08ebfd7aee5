// Finding and loading controller-link plugins (plugins/link_plugin.h) with
// QPluginLoader: from $K528_PLUGIN_PATH, the build tree (<bin>/../plugins)
// and the installed location (<prefix>/lib/k528studio/plugins). A file whose
// IID or "api" is not ours is refused with the reason; no plugin at all is
// not an error (the simulated machine needs none).
#pragma once

#include "link_plugin.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace k528::linkplugin {

struct Found {
    QString file;
    QString name, version, transport; // from the metadata
    LinkPlugin* plugin = nullptr;     // nullptr: refused
    QString refused;                  // why
};

// The folders searched, in order.
QStringList searchPath();
// Every plugin file of those folders, loaded or refused.
std::vector<Found> discover();
// One file (tests).
Found loadFile(const QString& path);
// The first usable plugin named `name` ("" = any), or nullptr with `error` set.
LinkPlugin* find(const QString& name, QString& error);

} // namespace k528::linkplugin
