// SPDX-License-Identifier: Apache-2.0
// The datasheet (`make datasheet`, sgm-eval datasheet): docs/datasheet.md written
// from the measured JSON reports only. Every figure on the page is read from a
// report and names it; a report that is absent gives "not measured: run `make X`".
#pragma once

#include <string>

namespace sgm::eval {

// The reports under a build directory (default "build"):
//   synth/**/summary.json   Yosys resources per configuration (`make synth`)
//   pnr/summary.json        routed LUT4 / FF / EBR / DSP / fmax per build (`make pnr`)
//   bench/report.json       the core's cycles per pixel and accuracy (`make bench`)
//   eval/report.json        the golden model's accuracy, Table I (`make eval`)
//   eval/pool.json          the golden model on the scene pool (`make eval-pool`)
// The page names each file by the path built from buildDir as given.
// Throws Error naming the file and field when a present report lacks a field it needs.
std::string datasheetMarkdown(const std::string& buildDir);

}  // namespace sgm::eval
