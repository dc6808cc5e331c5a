// relazione.hpp: a relazione di calcolo as the two documents it is filed as
// (issue 36; docs/user/relazione.md): the body a verificatore reads in one
// sitting (general part, one section of 2-4 pages per mechanism, summary,
// interventions, conclusions, the NTC 2018 §10.2 chapter) and the tabulati di
// calcolo a reviewer consults (every candidate's virtual-work table and
// capacity curve, each record and time history, the readings, the case
// file). Both built from the same assessment in the same document model,
// referring to each other by section number ("§T3.2"; resolve_references),
// and written side by side in every format (report_files.hpp).
#pragma once

#include "assess/report/document.hpp"

namespace assess {

/// The keys of the two documents (Document::key, Span::doc).
inline constexpr const char* relazione_key = "relazione";
inline constexpr const char* tabulati_key = "tabulati";

struct Relazione {
  Document body;      ///< key relazione_key; sections "1", "2" ...
  Document tabulati;  ///< key tabulati_key; sections "T1", "T2" ...
};

}  // namespace assess
