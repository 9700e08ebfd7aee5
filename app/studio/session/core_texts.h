// Core's texts that come as an id and its arguments, in the window's
// language: what is wrong with a machine file, a constants CSV or one of
// their items (profile::Problem), and the errors that carry one. The command
// line says the same ids in English from core's catalog (problem.cpp).
#pragma once

#include <QString>

#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

namespace k528::profile {
struct Problem;
class FileError;
} // namespace k528::profile
namespace k528::plc {
class DescriptionError;
} // namespace k528::plc
namespace k528::engine {
enum class Refusal : std::uint8_t;
struct OpResult;
} // namespace k528::engine
namespace k528::proveout {
struct Finding;
} // namespace k528::proveout
namespace k528::util {
struct Message;
} // namespace k528::util

namespace k528::studio {

// E.g. «C022 = 9 вне диапазона 10...5000 константы «УСКОРЕНИЕ 1»».
QString problemText(const profile::Problem& p);
// "<file>, line <n>: <problem>" («<файл>, строка <n>: …»).
QString fileErrorText(const profile::FileError& e);
// Any error core throws, for the window: a file's (fileErrorText), a machine
// description's (descriptionErrorText), one with
// a problem of core's catalog (the constants calculator's, a tool's, a
// database's refusal of an item), a database's (databaseErrorText), else
// core's own words.
QString coreErrorText(const std::exception& e);
// A file that cannot be read or written, the system's reason, an MQTT
// broker's address that is not one (util/system_texts.h's ids), e.g.
// «не удаётся записать /dev/full: на устройстве не осталось места».
QString systemText(const util::Message& m);
bool hasSystemText(std::string_view id);
// Reads the text file at `path` as core does (util::readInputFile: a
// regular file of at most 16 MiB); false with `error` saying why in the
// window's language («нет такого файла или папки», «это папка», …).
bool readTextFile(const QString& path, std::string& text, QString& error);
// A revision's note in the window's language: one core or the desktop
// wrote (db/notes.h: «встроенный профиль training-lathe (первый запуск)»),
// else the user's own words as written.
QString revisionNoteText(const std::string& summary);
bool hasNoteText(std::string_view id);
// Why the controller refused an operation (engine::Refusal), e.g. «Не в этом режиме».
QString refusalText(engine::Refusal r);
// Why, with the value and the limit (engine/refusal_texts.h's ids), e.g.
// «R-параметры — R0..R299, а не R300»; "" when accepted.
QString refusalText(const engine::OpResult& r);
bool hasRefusalText(std::string_view id);
// A prove-out finding (proveout::texts(): an id and its arguments), e.g.
// «Инструмент T1 задевает кулачки патрона: X40 Z-2».
QString findingText(const proveout::Finding& f);
bool hasFindingText(std::string_view id);
// What is wrong with a machine description («machines/x.json: inputs[0].name:
// «1x» — недопустимое имя …»): its file, the path in the document and the
// problem (plc/description_texts.h's ids) in the window's language.
QString descriptionErrorText(const plc::DescriptionError& e);
QString descriptionProblemText(const profile::Problem& p);
bool hasDescriptionText(std::string_view id);
// The id has a text here (studio.ui_language: every id of core's catalog has).
bool hasProblemText(std::string_view id);

} // namespace k528::studio
