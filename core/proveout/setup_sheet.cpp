#include "proveout/setup_sheet.h"

#include "catalog/rparams.h"
#include "engine/run.h"
#include "machine/run.h"
#include "profile/english.h"
#include "profile/problem.h"
#include "proveout/proveout.h"
#include "toolpath/programmed_path.h"
#include "util/json.h"

#include "units/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace k528::proveout {

namespace {

struct TextPair {
    SheetText key;
    std::string_view ru, en;
};

constexpr TextPair kTexts[] = {
    {SheetText::Title, "Карта наладки", "Setup sheet"},
    {SheetText::Machine, "Станок", "Machine"},
    {SheetText::File, "Файл программ", "Program file"},
    {SheetText::Blank, "Заготовка", "Blank"},
    {SheetText::NoBlank, "не задана (нет строки UCG в файле)", "not given (no UCG line in the file)"},
    {SheetText::BlankOuter, "наружный Ø%1 мм, длина %2 мм", "outside Ø%1 mm, length %2 mm"},
    {SheetText::BlankBore, "отверстие Ø%1 мм, глубина %2 мм", "bore Ø%1 mm, depth %2 mm"},
    {SheetText::Tools, "Инструмент", "Tools"},
    {SheetText::NoTools, "Инструмент станка не описан (tool.N.* в настройках станка)",
     "The machine's tools are not described (tool.N.* of the machine's settings)"},
    {SheetText::Station, "Поз.", "Station"},
    {SheetText::Kind, "Вид", "Kind"},
    {SheetText::Name, "Инструмент", "Tool"},
    {SheetText::TipRadius, "Радиус вершины, мм", "Tip radius, mm"},
    {SheetText::Orientation, "Ориентация", "Orientation"},
    {SheetText::OffsetR, "R коррекции", "Offset R"},
    {SheetText::OffsetX, "Корр. X, мм", "Offset X, mm"},
    {SheetText::OffsetZ, "Корр. Z, мм", "Offset Z, mm"},
    {SheetText::XDiameterNote, "X — на диаметр", "X is a diameter"},
    {SheetText::XRadiusNote, "X — на радиус", "X is a radius"},
    {SheetText::Programs, "Программы", "Programs"},
    {SheetText::Program, "Прогр.", "Program"},
    {SheetText::ProgramTitle, "Наименование", "Title"},
    {SheetText::CycleTime, "Время цикла", "Cycle time"},
    {SheetText::Subprogram, "подпрограмма", "subprogram"},
    {SheetText::NoCycleTime, "нет (прогон: %1)", "none (the run: %1)"},
    {SheetText::Presets, "Предустановки R-параметров", "R-parameters to preset"},
    {SheetText::NoPresets, "Станок не задаёт предустановок R-параметров", "The machine presets no R-parameters"},
    {SheetText::Parameter, "Параметр", "R"},
    {SheetText::Value, "Значение, дискр.", "Value, discretes"},
    {SheetText::ValueMm, "Значение, мм", "Value, mm"},
    {SheetText::Meaning, "Назначение", "Meaning"},
    {SheetText::ToolOffsetX, "коррекция X инструмента %1", "X offset of tool %1"},
    {SheetText::ToolOffsetZ, "коррекция Z инструмента %1", "Z offset of tool %1"},
    {SheetText::UserParameter, "параметр пользователя", "user parameter"},
    {SheetText::Seconds, "%1 с", "%1 s"},
    {SheetText::Total, "Всего по основным программам", "Total of the main programs"},
    {SheetText::Setter, "Наладчик", "Set up by"},
    {SheetText::Checked, "Проверил", "Checked by"},
    {SheetText::Date, "Дата", "Date"},
};

profile::ToolKind kindFrom(const std::string& s) {
    if (const auto k = profile::parseToolKind(s))
        return *k;
    throw std::runtime_error("setup sheet: unknown tool kind '" + s + "'");
}

} // namespace

std::string_view sheetText(SheetText t, bool russian) {
    for (const TextPair& p : kTexts)
        if (p.key == t)
            return russian ? p.ru : p.en;
    return {};
}

std::string_view toolKindText(profile::ToolKind k, bool russian) {
    switch (k) {
    case profile::ToolKind::Turning:
        return russian ? "проходной" : "turning";
    case profile::ToolKind::Facing:
        return russian ? "подрезной" : "facing";
    case profile::ToolKind::Grooving:
        return russian ? "канавочный" : "grooving";
    case profile::ToolKind::Boring:
        return russian ? "расточной" : "boring";
    case profile::ToolKind::Drill:
        return russian ? "сверло" : "drill";
    case profile::ToolKind::Threading:
        return russian ? "резьбовой" : "threading";
    }
    return {};
}

std::string sheetMm(double v, int decimals) {
    if (!std::isfinite(v))
        return "—";
    return units::formatTrimmed(v, decimals);
}

SetupSheet setupSheet(const profile::MachineProfile& profile, const program::ProgramStore& store,
                      std::string_view fileText, std::string file,
                      const std::map<int, std::int64_t>& rPresets, const std::optional<stock::Blank>& blank,
                      bool withCycleTimes) {
    SetupSheet s;
    s.machineName = profile.name;
    s.machineTitle = profile::titleText(profile, false);
    s.machineTitleEn = profile::titleText(profile, true);
    s.file = std::move(file);
    s.xDiameter = profile::axisScale(profile, catalog::Axis::X).diameter;
    s.blank = blank ? blank : stock::findUcg(fileText);
    if (s.blank)
        s.ucg = stock::formatUcg(*s.blank);

    const std::vector<profile::Tool> tools = profile::tools(profile);
    for (const profile::Tool& t : tools) {
        const profile::ToolOffsets o = profile::toolOffsets(t, profile, rPresets);
        s.tools.push_back({t, profile::toolName(profile, t, true), o.xMm, o.zMm});
    }

    const std::vector<int> mains = mainPrograms(store);
    for (const program::Program& p : store.programs()) {
        SheetProgram sp;
        sp.number = p.number;
        sp.title = p.title.value_or("");
        sp.main = std::find(mains.begin(), mains.end(), p.number) != mains.end();
        if (sp.main) {
            toolpath::PathOptions po;
            po.preview.rPresets = rPresets;
            const toolpath::ProgrammedPath path = toolpath::programmedPath(profile, store, p.number, po);
            sp.frames = path.run.frames;
            sp.run = "not_run";
            if (withCycleTimes && path.run.status == engine::PreviewStatus::Completed) {
                try {
                    const machine::CycleTime t = machine::cycleTime(profile, store, p.number, rPresets);
                    sp.cycleSeconds = t.seconds;
                    sp.run = engine::runStatusName(t.run.status);
                } catch (const std::invalid_argument&) { // the machine cannot run it as set up
                }
            }
        }
        s.programs.push_back(std::move(sp));
    }

    std::map<int, std::int64_t> presets = profile.r;
    for (const auto& [n, v] : rPresets)
        presets[n] = v;
    for (const auto& [n, v] : presets) {
        SheetPreset p;
        p.number = n;
        p.value = v;
        for (const profile::Tool& t : tools) {
            if (t.offsetR < 0)
                continue;
            if (n == t.offsetR || n == t.offsetR + 1) {
                const bool x = n == t.offsetR;
                const std::vector<std::string> args{std::to_string(t.station)};
                p.meaningRu = profile::fillPattern(sheetText(x ? SheetText::ToolOffsetX : SheetText::ToolOffsetZ, true), args);
                p.meaningEn = profile::fillPattern(sheetText(x ? SheetText::ToolOffsetX : SheetText::ToolOffsetZ, false), args);
                p.mm = units::discToMm(v, profile::axisScale(profile, x ? catalog::Axis::X : catalog::Axis::Z));
            }
        }
        if (p.meaningRu.empty()) {
            if (const catalog::RParamDef* d = catalog::findRParam(n); d && d->reserved()) {
                p.meaningRu = std::string(d->meaningRu);
                p.meaningEn = std::string(d->meaningEn);
                switch (d->unit) {
                case catalog::RUnit::DiscX:
                case catalog::RUnit::DiscXPerMin:
                    p.mm = units::discToMm(v, profile::axisScale(profile, catalog::Axis::X));
                    break;
                case catalog::RUnit::DiscZ:
                case catalog::RUnit::DiscZPerMin:
                    p.mm = units::discToMm(v, profile::axisScale(profile, catalog::Axis::Z));
                    break;
                default:
                    break;
                }
            }
        }
        s.presets.push_back(std::move(p));
    }
    return s;
}

std::string sheetJson(const SetupSheet& s) {
    Json o = Json::object();
    o["machine"] = s.machineName;
    o["machine_title"] = s.machineTitle;
    o["machine_title_en"] = s.machineTitleEn;
    o["file"] = s.file;
    o["x_diameter"] = s.xDiameter;
    o["blank"] = s.ucg.empty() ? Json() : Json(s.ucg);
    Json tools = Json::array();
    for (const SheetTool& t : s.tools) {
        Json j = Json::object();
        j["station"] = t.tool.station;
        j["kind"] = std::string(profile::toolKindName(t.tool.kind));
        j["name"] = t.tool.name;
        j["name_en"] = t.nameEn;
        j["tip_radius_mm"] = t.tool.tipRadiusMm;
        j["orientation"] = t.tool.orientation();
        j["width_mm"] = t.tool.widthMm;
        j["height_mm"] = t.tool.heightMm;
        j["max_depth_mm"] = t.tool.maxDepthMm;
        j["offset_r"] = t.tool.offsetR;
        j["offset_x_mm"] = t.offsetXMm;
        j["offset_z_mm"] = t.offsetZMm;
        tools.push_back(std::move(j));
    }
    o["tools"] = std::move(tools);
    Json programs = Json::array();
    for (const SheetProgram& p : s.programs) {
        Json j = Json::object();
        j["number"] = p.number;
        j["title"] = p.title;
        j["main"] = p.main;
        j["cycle_time_s"] = p.cycleSeconds ? Json(*p.cycleSeconds) : Json();
        j["run"] = p.run;
        j["frames"] = p.frames;
        programs.push_back(std::move(j));
    }
    o["programs"] = std::move(programs);
    Json presets = Json::array();
    for (const SheetPreset& p : s.presets) {
        Json j = Json::object();
        j["r"] = p.number;
        j["value"] = p.value;
        j["mm"] = p.mm ? Json(*p.mm) : Json();
        j["meaning_ru"] = p.meaningRu;
        j["meaning_en"] = p.meaningEn;
        presets.push_back(std::move(j));
    }
    o["presets"] = std::move(presets);
    return json::dump(o, 1);
}

SetupSheet sheetFromJson(std::string_view text) {
    SetupSheet s;
    try {
        const Json o = json::parse(text);
        s.machineName = o.at("machine").get<std::string>();
        s.machineTitle = o.at("machine_title").get<std::string>();
        s.machineTitleEn = o.at("machine_title_en").get<std::string>();
        s.file = o.at("file").get<std::string>();
        s.xDiameter = o.at("x_diameter").get<bool>();
        if (!o.at("blank").is_null()) {
            s.ucg = o.at("blank").get<std::string>();
            s.blank = stock::parseUcg(s.ucg);
        }
        for (const Json& j : o.at("tools")) {
            SheetTool t;
            t.tool.station = j.at("station").get<int>();
            t.tool.kind = kindFrom(j.at("kind").get<std::string>());
            t.tool.name = j.at("name").get<std::string>();
            t.nameEn = j.at("name_en").get<std::string>();
            t.tool.tipRadiusMm = j.at("tip_radius_mm").get<double>();
            const std::string orient = j.at("orientation").get<std::string>();
            if (orient.size() == 4) {
                t.tool.zDirection = orient[0] == '-' ? -1 : +1;
                t.tool.xDirection = orient[2] == '-' ? -1 : +1;
            }
            t.tool.widthMm = j.at("width_mm").get<double>();
            t.tool.heightMm = j.at("height_mm").get<double>();
            t.tool.maxDepthMm = j.at("max_depth_mm").get<double>();
            t.tool.offsetR = j.at("offset_r").get<int>();
            t.offsetXMm = j.at("offset_x_mm").get<double>();
            t.offsetZMm = j.at("offset_z_mm").get<double>();
            s.tools.push_back(std::move(t));
        }
        for (const Json& j : o.at("programs")) {
            SheetProgram p;
            p.number = j.at("number").get<int>();
            p.title = j.at("title").get<std::string>();
            p.main = j.at("main").get<bool>();
            if (!j.at("cycle_time_s").is_null())
                p.cycleSeconds = j.at("cycle_time_s").get<double>();
            p.run = j.at("run").get<std::string>();
            p.frames = j.at("frames").get<std::int64_t>();
            s.programs.push_back(std::move(p));
        }
        for (const Json& j : o.at("presets")) {
            SheetPreset p;
            p.number = j.at("r").get<int>();
            p.value = j.at("value").get<std::int64_t>();
            if (!j.at("mm").is_null())
                p.mm = j.at("mm").get<double>();
            p.meaningRu = j.at("meaning_ru").get<std::string>();
            p.meaningEn = j.at("meaning_en").get<std::string>();
            s.presets.push_back(std::move(p));
        }
    } catch (const json::ParseError& e) {
        throw std::runtime_error(std::string("setup sheet: ") + e.what());
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(std::string("setup sheet: ") + e.what());
    }
    return s;
}

} // namespace k528::proveout
