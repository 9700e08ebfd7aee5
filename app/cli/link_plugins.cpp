#include "link_plugins.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>
#include <QPluginLoader>
#include <QProcessEnvironment>

#ifndef K528_HELPER_DIR_FROM_BIN
#define K528_HELPER_DIR_FROM_BIN "../lib/k528studio"
#endif
#ifndef K528_PLUGIN_INSTALL_DIR
#define K528_PLUGIN_INSTALL_DIR ""
#endif

namespace k528::linkplugin {

QStringList searchPath() {
    QStringList dirs;
    const QString env = qEnvironmentVariable("K528_PLUGIN_PATH");
    if (!env.isEmpty())
        dirs << env.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    // The build tree (build/bin and build/plugins), then the installed layout
    // seen from either program: k528-link lives in the helper folder, whose
    // plugins/ is beside it; the studio in /usr/bin reaches it as k528 reaches
    // its helpers (helper_path.h).
    const QString bin = QCoreApplication::applicationDirPath();
    dirs << QDir::cleanPath(bin + "/../plugins") << QDir::cleanPath(bin + "/plugins")
         << QDir::cleanPath(bin + "/" K528_HELPER_DIR_FROM_BIN "/plugins");
    if (QString(K528_PLUGIN_INSTALL_DIR) != "")
        dirs << QStringLiteral(K528_PLUGIN_INSTALL_DIR);
    dirs.removeDuplicates();
    return dirs;
}

Found loadFile(const QString& path) {
    Found f;
    f.file = path;
    QPluginLoader loader(path);
    const QJsonObject meta = loader.metaData();
    if (meta.isEmpty()) {
        f.refused = QStringLiteral("not a Qt plugin");
        return f;
    }
    const QJsonObject data = meta.value("MetaData").toObject();
    f.name = data.value("name").toString();
    f.version = data.value("version").toString();
    f.transport = data.value("transport").toString();
    if (meta.value("IID").toString() != QLatin1String(K528_LINK_PLUGIN_IID)) {
        f.refused = QStringLiteral("IID %1 is not %2").arg(meta.value("IID").toString(), K528_LINK_PLUGIN_IID);
        return f;
    }
    if (data.value("api").toInt(-1) != kApi) {
        f.refused = QStringLiteral("plugin api %1, this program needs %2").arg(data.value("api").toInt(-1)).arg(kApi);
        return f;
    }
    if (f.name.isEmpty() || f.version.isEmpty() || f.transport.isEmpty()) {
        f.refused = QStringLiteral("metadata without name, version or transport");
        return f;
    }
    QObject* o = loader.instance();
    f.plugin = o ? qobject_cast<LinkPlugin*>(o) : nullptr;
    if (!f.plugin)
        f.refused = o ? QStringLiteral("does not implement the link interface") : loader.errorString();
    return f;
}

std::vector<Found> discover() {
    std::vector<Found> out;
    for (const QString& d : searchPath()) {
        const QDir dir(d);
        for (const QFileInfo& fi : dir.entryInfoList({"*.so", "*.dll", "*.dylib"}, QDir::Files, QDir::Name))
            out.push_back(loadFile(fi.absoluteFilePath()));
    }
    return out;
}

LinkPlugin* find(const QString& name, QString& error) {
    const std::vector<Found> all = discover();
    for (const Found& f : all)
        if (f.plugin && (name.isEmpty() || f.name == name))
            return f.plugin;
    error = QStringLiteral("no controller-link plugin%1 found in %2")
                .arg(name.isEmpty() ? QString() : " '" + name + "'", searchPath().join(", "));
    for (const Found& f : all)
        if (!f.plugin)
            error += QStringLiteral("; refused %1: %2").arg(f.file, f.refused);
    return nullptr;
}

} // namespace k528::linkplugin
