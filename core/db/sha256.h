// SHA-256 (FIPS 180-4), the checksum of program texts in the database.
//
// Every stored program revision carries the SHA-256 of its text (UTF-8 bytes
// exactly as stored, lines ending in "\n"); loading a program recomputes it
// and refuses a text that no longer matches. SHA-256 rather than CRC-32: the
// checksum also identifies a program across machines and revisions ("is L11
// on both grinders the same text?"), where a 32-bit value would collide.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace k528::db {

class Sha256 {
public:
    Sha256();
    void update(std::string_view data);
    // The digest; the object must not be updated afterwards.
    std::array<std::uint8_t, 32> finish();

private:
    void block(const std::uint8_t* p);
    std::array<std::uint32_t, 8> h_;
    std::array<std::uint8_t, 64> buf_{};
    std::size_t used_ = 0;
    std::uint64_t bytes_ = 0;
};

// Lower-case hex digest of `data` (64 characters).
std::string sha256Hex(std::string_view data);

} // namespace k528::db
