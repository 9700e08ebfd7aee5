#include "util/system_texts.h"

#include <array>
#include <cerrno>
#include <cstring>

namespace k528::util {

namespace {

// The Russian of a reason continues our sentence («не удаётся записать
// /dev/full: на устройстве не осталось места»), so it starts in lower case;
// the English is glibc's strerror() text, as the command line said it before.
constexpr std::array kTexts = {
    // A file that cannot be read or written, the path as %1, why as %2.
    CatalogText{"io.cannot-open", "не удаётся открыть %1: %2", "cannot open %1: %2"},
    CatalogText{"io.cannot-read", "не удаётся прочитать %1: %2", "cannot read %1: %2"},
    CatalogText{"io.cannot-write", "не удаётся записать %1: %2", "cannot write %1: %2"},
    CatalogText{"io.cannot-read-stdin", "не удаётся прочитать стандартный ввод: %1", "cannot read standard input: %1"},
    CatalogText{"io.cannot-write-stdout", "не удаётся записать стандартный вывод: %1",
                "cannot write standard output: %1"},
    // Why.
    CatalogText{"io.directory", "это папка", "it is a directory"},
    CatalogText{"io.not-regular", "это %1, а не обычный файл (k528 читает только файлы программ и станков)",
                "it is %1, not a regular file (k528 reads program and machine files only)"},
    CatalogText{"io.kind.directory", "папка", "a directory"},
    CatalogText{"io.kind.character-device", "символьное устройство", "a character device"},
    CatalogText{"io.kind.block-device", "блочное устройство", "a block device"},
    CatalogText{"io.kind.fifo", "FIFO (именованный канал)", "a FIFO (named pipe)"},
    CatalogText{"io.kind.socket", "сокет", "a socket"},
    CatalogText{"io.kind.other", "особый файл", "a special file"},
    CatalogText{"io.too-large",
                "он больше %1 МиБ, а больше k528 не читает (K528-05 хранит не более 99 программ по 999 кадров — "
                "около 3 МБ текста)",
                "it is larger than %1 MiB, the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, "
                "about 3 MB of text)"},
    CatalogText{"io.no-memory", "не хватает памяти", "not enough memory"},
    CatalogText{"io.write-directory", "это папка; укажите имя файла", "it is a directory; give a file name"},
    CatalogText{"io.write-kind", "это не обычный файл, не FIFO и не символьное устройство",
                "it is not a regular file, a FIFO or a character device"},
    CatalogText{"io.create-in-folder", "в его папке %1 нельзя создать файл: %2",
                "cannot create a file in its folder %1: %2"},
    CatalogText{"io.not-open", "он не открыт", "it is not open"},
    CatalogText{"io.write-failed", "запись не удалась", "a write failed"},
    // An MQTT broker's address as a user types it (k528 shop publish --mqtt,
    // the studio's shop view); %1 the text given.
    CatalogText{"mqtt.url-scheme", "«%1» — не mqtt://ХОСТ[:ПОРТ] (MQTT без шифрования; TLS не поддерживается)",
                "'%1' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)"},
    CatalogText{"mqtt.url-port", "«%1»: порт — 1..65535", "'%1': the port is 1..65535"},
    CatalogText{"mqtt.url-host", "«%1»: после mqtt:// нет имени или адреса хоста",
                "'%1': no host name or address after mqtt://"},
    // The system's reasons (errno).
    CatalogText{"errno.EPERM", "операция не разрешена", "Operation not permitted"},
    CatalogText{"errno.ENOENT", "нет такого файла или папки", "No such file or directory"},
    CatalogText{"errno.EINTR", "системный вызов прерван", "Interrupted system call"},
    CatalogText{"errno.EIO", "ошибка ввода-вывода", "Input/output error"},
    CatalogText{"errno.ENXIO", "нет такого устройства или адреса", "No such device or address"},
    CatalogText{"errno.EBADF", "неверный дескриптор файла", "Bad file descriptor"},
    CatalogText{"errno.EAGAIN", "ресурс временно недоступен", "Resource temporarily unavailable"},
    CatalogText{"errno.ENOMEM", "не хватает памяти", "Cannot allocate memory"},
    CatalogText{"errno.EACCES", "доступ запрещён", "Permission denied"},
    CatalogText{"errno.EBUSY", "устройство или ресурс занято", "Device or resource busy"},
    CatalogText{"errno.EEXIST", "файл уже существует", "File exists"},
    CatalogText{"errno.EXDEV", "ссылка между файловыми системами невозможна", "Invalid cross-device link"},
    CatalogText{"errno.ENODEV", "нет такого устройства", "No such device"},
    CatalogText{"errno.ENOTDIR", "это не папка", "Not a directory"},
    CatalogText{"errno.EISDIR", "это папка", "Is a directory"},
    CatalogText{"errno.EINVAL", "недопустимый аргумент", "Invalid argument"},
    CatalogText{"errno.ENFILE", "слишком много открытых файлов в системе", "Too many open files in system"},
    CatalogText{"errno.EMFILE", "слишком много открытых файлов", "Too many open files"},
    CatalogText{"errno.ETXTBSY", "текстовый файл занят", "Text file busy"},
    CatalogText{"errno.EFBIG", "файл слишком велик", "File too large"},
    CatalogText{"errno.ENOSPC", "на устройстве не осталось места", "No space left on device"},
    CatalogText{"errno.ESPIPE", "недопустимое позиционирование", "Illegal seek"},
    CatalogText{"errno.EROFS", "файловая система только для чтения", "Read-only file system"},
    CatalogText{"errno.EMLINK", "слишком много ссылок", "Too many links"},
    CatalogText{"errno.EPIPE", "канал разорван", "Broken pipe"},
    CatalogText{"errno.ENAMETOOLONG", "слишком длинное имя файла", "File name too long"},
    CatalogText{"errno.ELOOP", "слишком много уровней символических ссылок", "Too many levels of symbolic links"},
    CatalogText{"errno.ENOTEMPTY", "папка не пуста", "Directory not empty"},
    CatalogText{"errno.EDQUOT", "превышена дисковая квота", "Disk quota exceeded"},
    CatalogText{"errno.ESTALE", "устаревший дескриптор файла", "Stale file handle"},
    CatalogText{"errno.EOVERFLOW", "значение слишком велико для типа данных", "Value too large for defined data type"},
    CatalogText{"errno.ENOTSUP", "операция не поддерживается", "Operation not supported"},
    CatalogText{"errno.ECONNREFUSED", "в соединении отказано", "Connection refused"},
    CatalogText{"errno.ETIMEDOUT", "время ожидания соединения истекло", "Connection timed out"},
    // Any other: its number and the C library's own words, quoted.
    CatalogText{"errno.other", "системная ошибка %1 («%2»)", "%2 (error %1)"},
};

struct ErrnoId {
    int number;
    const char* id;
};

constexpr ErrnoId kErrnos[] = {
    {EPERM, "errno.EPERM"},   {ENOENT, "errno.ENOENT"},   {EINTR, "errno.EINTR"},
    {EIO, "errno.EIO"},       {ENXIO, "errno.ENXIO"},     {EBADF, "errno.EBADF"},
    {EAGAIN, "errno.EAGAIN"}, {ENOMEM, "errno.ENOMEM"},   {EACCES, "errno.EACCES"},
    {EBUSY, "errno.EBUSY"},   {EEXIST, "errno.EEXIST"},   {EXDEV, "errno.EXDEV"},
    {ENODEV, "errno.ENODEV"}, {ENOTDIR, "errno.ENOTDIR"}, {EISDIR, "errno.EISDIR"},
    {EINVAL, "errno.EINVAL"}, {ENFILE, "errno.ENFILE"},   {EMFILE, "errno.EMFILE"},
    {ETXTBSY, "errno.ETXTBSY"}, {EFBIG, "errno.EFBIG"},   {ENOSPC, "errno.ENOSPC"},
    {ESPIPE, "errno.ESPIPE"}, {EROFS, "errno.EROFS"},     {EMLINK, "errno.EMLINK"},
    {EPIPE, "errno.EPIPE"},   {ENAMETOOLONG, "errno.ENAMETOOLONG"}, {ELOOP, "errno.ELOOP"},
    {ENOTEMPTY, "errno.ENOTEMPTY"}, {EDQUOT, "errno.EDQUOT"}, {ESTALE, "errno.ESTALE"},
    {EOVERFLOW, "errno.EOVERFLOW"}, {ENOTSUP, "errno.ENOTSUP"}, {ECONNREFUSED, "errno.ECONNREFUSED"},
    {ETIMEDOUT, "errno.ETIMEDOUT"},
};

} // namespace

Message message(std::string id, std::vector<std::string> args, std::vector<Message> within) {
    return Message{std::move(id), std::move(args), std::move(within)};
}

TextCatalog systemTexts() { return TextCatalog(kTexts); }

std::string systemText(const Message& m, bool russian) {
    std::vector<std::string> all = m.args;
    for (const Message& w : m.within)
        all.push_back(systemText(w, russian));
    return systemTexts().render(m.id, all, russian);
}

Message systemError(int errnum) {
    for (const ErrnoId& e : kErrnos)
        if (e.number == errnum)
            return message(e.id);
    return message("errno.other", {std::to_string(errnum), std::strerror(errnum)});
}

} // namespace k528::util
