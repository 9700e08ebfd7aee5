// A plugin the loader must refuse: built twice, with a foreign IID and with
// another api number (tests/link/CMakeLists.txt).
#include "link_plugin.h"

class FakePlugin : public QObject, public k528::linkplugin::LinkPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID FAKE_IID FILE FAKE_JSON)
    Q_INTERFACES(k528::linkplugin::LinkPlugin)
public:
    QStringList ports() const override { return {}; }
    std::unique_ptr<k528::linkplugin::ClientTransport> openClient(const k528::linkplugin::LineSettings&, QString& e) override {
        e = "fake";
        return nullptr;
    }
    std::unique_ptr<k528::linkplugin::Server> openServer(const k528::linkplugin::LineSettings&,
                                                         k528::linkplugin::RegisterHandler&, const QString&, QString& e) override {
        e = "fake";
        return nullptr;
    }
};

#include "fake_plugin.moc"
