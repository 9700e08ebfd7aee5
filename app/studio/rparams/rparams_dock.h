// The dock «R-parameters» (dock.rparams): R0..R299 of the controller the
// window shows, live (RParamsModel), edited with that controller's rules
// (the simulation: РУЧНОЙ screen 3; a real one: F7 «РАБОТА С ПЭВМ», told by
// the dock's notice), and the machine's presets: the value
// of a parameter kept as its preset (a new revision of the machine in the
// database, with a note), a preset removed, the presets put into the
// controller again.
#pragma once

#include "parameters/parameter_table_pane.h"
#include "profile/profile.h"

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

class QComboBox;
class QDockWidget;
class QMainWindow;
class QToolButton;

namespace k528::studio {

class MachineStore;
class RParamsFilter;
class RParamsModel;
class TrialPartDialog;

class RParamsPane : public ParameterTablePane {
    Q_OBJECT
public:
    RParamsPane(ViewedController& viewed, const profile::MachineProfile& machine, QWidget* parent = nullptr);
    ~RParamsPane() override;

    RParamsModel* model() const { return model_; }
    RParamsFilter* filter() const { return filter_; }
    void selectR(int number);

    // Presets: kept as the machine's next revision; returns the revision (0: not kept).
    // `given`: the revision's note as stored (db/notes.h); "" the user's, or ours naming the presets.
    int keepPresets(const std::map<int, std::optional<std::int64_t>>& presets, const QString& given = {});
    int keepSelectedAsPreset();
    int removeSelectedPreset();
    int keepAllAsPresets(); // every writable R that is not 0, as «keep the memory» does
    void applyPresets();    // the machine's presets into the controller (one after another)
    // The trial part's dialog (not shown yet) on the machine as the database
    // holds it; its «Keep» keeps the correction (keepTrialCorrection).
    TrialPartDialog* trialPartDialog();
    // R`r` = `value` kept as a preset with `note`, then set in the controller.
    int keepTrialCorrection(int r, std::int64_t value, const QString& note);

private:
    void retranslatePane() override;
    void applyFrom(std::vector<std::pair<int, std::int64_t>> presets, std::size_t next);
    MachineStore* store_;
    RParamsModel* model_;
    RParamsFilter* filter_;
    QComboBox* show_;
    QToolButton* keep_;
    QToolButton* remove_;
    QToolButton* keepAll_;
    QToolButton* apply_;
    QToolButton* trial_;
};

QDockWidget* addRParamsDock(QMainWindow* window, ViewedController& viewed, const profile::MachineProfile& machine);

} // namespace k528::studio
