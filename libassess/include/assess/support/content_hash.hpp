// content_hash.hpp: a 64-bit content hash (FNV-1a) of bytes, to tell whether
// a generated file is still the one built from its inputs (the record
// library's catalogue and precomputed spectra). It detects accidental change,
// not tampering: FNV-1a is not a cryptographic hash.
#pragma once

#include "assess/support/input_file.hpp"

#include <cstdint>
#include <string>

namespace assess {

/// FNV-1a, 64 bits (Fowler, Noll & Vo; offset basis 14695981039346656037,
/// prime 1099511628211) of `size` bytes at `data`, continuing from `seed`.
std::uint64_t content_hash(const void* data, std::size_t size,
                           std::uint64_t seed = 14695981039346656037ull);
/// The same of a string's bytes.
std::uint64_t content_hash(const std::string& bytes);
/// 16 lower-case hexadecimal digits.
std::string hash_hex(std::uint64_t h);
/// The hash of a file's bytes, read by the bounded reader as a `kind`
/// (input_file.hpp). @throws InputError if it cannot be read
std::uint64_t file_content_hash(const std::string& path, const InputKind& kind);

}  // namespace assess
