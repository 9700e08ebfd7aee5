#pragma once
// libpq is loaded when a PostgreSQL database is first opened, not when a
// program starts: linked at start it brings 18 shared libraries (Kerberos,
// LDAP, GnuTLS, …) and costs every `k528` command ~14 ms before main(), also
// the ones that never touch a server. libpq_lazy.cpp defines the PQ*
// functions that postgres*.cpp call; each forwards to the libpq loaded by
// dlopen on first use.

namespace k528::db::libpq {

// Why libpq could not be loaded (to be said to the user), or nullptr when it
// is loaded. Loads it on the first call.
const char* loadError();

} // namespace k528::db::libpq
