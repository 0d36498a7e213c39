// SPDX-License-Identifier: Apache-2.0
// Small helpers shared by the report writers (tools/, synth/*_summary.cpp,
// bench/sgm_bench.cpp): the fixed-point number formatter, whole-file and
// line readers, the key=value meta.txt reader and directory listings.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace sgm::eval {

// printf("%.*f", decimals, value): fixed(3.14159, 2) == "3.14".
std::string fixed(double value, int decimals);

// The whole file. Throws Error naming the file when it cannot be read.
std::string readTextFile(const std::string& path);

// The file's lines (without their '\n'); none when the file cannot be read.
std::vector<std::string> readLines(const std::string& path);

// The first line of a file; empty when the file cannot be read.
std::string readFirstLine(const std::string& path);

// A key=value file (meta.txt of the synth/ and pnr/ runs, written by synth/*.mk):
// every line with a '=' gives key (before the first '=') -> value (after it);
// other lines are skipped, a later key replaces an earlier one. A missing or
// unreadable file reads as empty unless required (then it throws Error).
std::map<std::string, std::string> readMeta(const std::string& path, bool required = false);

// The value of key in meta, or fallback when absent.
std::string metaValue(const std::map<std::string, std::string>& meta, const std::string& key,
                      const std::string& fallback = "");

bool isFile(const std::string& path);
bool isDirectory(const std::string& path);

// The names in a directory, sorted, without hidden entries (names starting with
// '.', "." and ".." among them); none when it cannot be read.
std::vector<std::string> listDir(const std::string& path);

}  // namespace sgm::eval
