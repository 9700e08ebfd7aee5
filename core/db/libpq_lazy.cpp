// The PQ* functions the PostgreSQL backend uses, each forwarding to libpq.so.5
// loaded on first use (see libpq_lazy.h). A function postgres*.cpp starts to
// use must be added to K528_LIBPQ_FUNCTIONS: until it is, the link fails with
// an undefined reference naming it, as the executables no longer link libpq.
#include "db/libpq_lazy.h"

#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <libpq-fe.h>
#include <mutex>
#include <string>

// X(return type, name, (parameters), (arguments))
#define K528_LIBPQ_FUNCTIONS(X)                                                                    \
    X(PGconn*, PQconnectdbParams, (const char* const* k, const char* const* v, int e), (k, v, e))  \
    X(void, PQfinish, (PGconn * c), (c))                                                           \
    X(void, PQreset, (PGconn * c), (c))                                                            \
    X(ConnStatusType, PQstatus, (const PGconn* c), (c))                                            \
    X(PGTransactionStatusType, PQtransactionStatus, (const PGconn* c), (c))                        \
    X(char*, PQerrorMessage, (const PGconn* c), (c))                                               \
    X(int, PQbackendPID, (const PGconn* c), (c))                                                   \
    X(PGpipelineStatus, PQpipelineStatus, (const PGconn* c), (c))                                  \
    X(PQnoticeReceiver, PQsetNoticeReceiver, (PGconn * c, PQnoticeReceiver f, void* a), (c, f, a)) \
    X(PGresult*, PQexec, (PGconn * c, const char* q), (c, q))                                      \
    X(PGresult*, PQprepare, (PGconn * c, const char* n, const char* q, int np, const Oid* t),      \
      (c, n, q, np, t))                                                                            \
    X(PGresult*, PQexecPrepared,                                                                   \
      (PGconn * c, const char* n, int np, const char* const* v, const int* l, const int* f,        \
       int r),                                                                                     \
      (c, n, np, v, l, f, r))                                                                      \
    X(int, PQsendQueryParams,                                                                      \
      (PGconn * c, const char* q, int np, const Oid* t, const char* const* v, const int* l,        \
       const int* f, int r),                                                                       \
      (c, q, np, t, v, l, f, r))                                                                   \
    X(int, PQsendQueryPrepared,                                                                    \
      (PGconn * c, const char* n, int np, const char* const* v, const int* l, const int* f,        \
       int r),                                                                                     \
      (c, n, np, v, l, f, r))                                                                      \
    X(PGresult*, PQgetResult, (PGconn * c), (c))                                                   \
    X(int, PQconsumeInput, (PGconn * c), (c))                                                      \
    X(int, PQenterPipelineMode, (PGconn * c), (c))                                                 \
    X(int, PQexitPipelineMode, (PGconn * c), (c))                                                  \
    X(int, PQpipelineSync, (PGconn * c), (c))                                                      \
    X(PGnotify*, PQnotifies, (PGconn * c), (c))                                                    \
    X(ExecStatusType, PQresultStatus, (const PGresult* r), (r))                                    \
    X(char*, PQresultErrorMessage, (const PGresult* r), (r))                                       \
    X(char*, PQresultErrorField, (const PGresult* r, int f), (r, f))                               \
    X(int, PQntuples, (const PGresult* r), (r))                                                    \
    X(int, PQnfields, (const PGresult* r), (r))                                                    \
    X(char*, PQfname, (const PGresult* r, int f), (r, f))                                          \
    X(Oid, PQftype, (const PGresult* r, int f), (r, f))                                            \
    X(char*, PQcmdTuples, (PGresult * r), (r))                                                     \
    X(char*, PQgetvalue, (const PGresult* r, int t, int f), (r, t, f))                             \
    X(int, PQgetlength, (const PGresult* r, int t, int f), (r, t, f))                              \
    X(int, PQgetisnull, (const PGresult* r, int t, int f), (r, t, f))                              \
    X(void, PQclear, (PGresult * r), (r))                                                          \
    X(void, PQfreemem, (void* p), (p))

namespace {

struct Libpq {
#define K528_POINTER(ret, name, params, args) ret(*name) params = nullptr;
    K528_LIBPQ_FUNCTIONS(K528_POINTER)
#undef K528_POINTER
    std::string error; // empty when every function was found
};

// The soname of Debian's libpq5 (the ABI libpq-fe.h of libpq-dev describes).
constexpr const char* kSoname = "libpq.so.5";

Libpq load() {
    Libpq l;
    void* h = dlopen(kSoname, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char* why = dlerror();
        l.error = std::string("the PostgreSQL client library ") + kSoname +
                  " cannot be loaded (Debian package libpq5): " + (why ? why : "not found");
        return l;
    }
#define K528_RESOLVE(ret, name, params, args)                                                      \
    l.name = reinterpret_cast<ret(*) params>(dlsym(h, #name));                                     \
    if (!l.name && l.error.empty())                                                                \
        l.error = std::string("the PostgreSQL client library ") + kSoname +                        \
                  " has no " #name " (too old a libpq5)";
    K528_LIBPQ_FUNCTIONS(K528_RESOLVE)
#undef K528_RESOLVE
    return l; // the handle stays open for the life of the process
}

const Libpq& libpq() {
    static const Libpq l = load(); // thread-safe once (C++11 static init)
    return l;
}

// Only reached when a PQ* function is called although loadError() said why it
// cannot be: a programming error, not a user's.
[[noreturn]] void missing(const char* name) {
    std::fprintf(stderr, "k528: %s called without libpq: %s\n", name, libpq().error.c_str());
    std::abort();
}

} // namespace

namespace k528::db::libpq {

const char* loadError() {
    const auto& l = ::libpq();
    return l.error.empty() ? nullptr : l.error.c_str();
}

} // namespace k528::db::libpq

extern "C" {
#define K528_FORWARD(ret, name, params, args)                                                      \
    ret name params {                                                                              \
        const auto fn_ = libpq().name;                                                             \
        if (!fn_)                                                                                  \
            missing(#name);                                                                        \
        return fn_ args;                                                                           \
    }
K528_LIBPQ_FUNCTIONS(K528_FORWARD)
#undef K528_FORWARD
}
