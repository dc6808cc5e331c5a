// messages_ties.cpp: the tie rods' part of the report's message catalogue
// (issue 29), Italian and English; keys "tie.*", looked up by msg() of
// messages.cpp. "{}" are fmt placeholders (msgf). The Italian edition has no
// English word and no certainty tag: the readings (tags included) are the
// "tie.reading.*" entries, for the appendix "Ipotesi e letture adottate".
#include "report/messages_ties.hpp"

namespace assess::detail {

const std::map<std::string, std::pair<std::string, std::string>>& tie_messages() {
  static const std::map<std::string, std::pair<std::string, std::string>> m{
      {"tie.title", {"Intervento: catene (tiranti)", "Intervention: tie rods"}},
      {"tie.no_break", {"nessuna rottura in alcuna analisi", "no break in any analysis"}},
      {"tie.no_force", {"la catena non è sollecitata in questo stato (forza nulla)", "the tie carries no force in this state"}},
      {"tie.wall_in_tab", {"Le tabelle complete delle verifiche di ogni catena in ogni stato, i cunei di punzonamento, le formule delle resistenze con le loro fonti e i dettagli costruttivi delle catene della parete sono nei tabulati, §{§}.",
        "The full tables of every tie's checks in each state, the punched wedges, the strength formulas with their sources and the detailing of the wall's ties are in the tabulati, §{§}."}},
      {"tie.runs_in_tab", {"La forza massima e l'esito delle catene in ogni analisi dello stato di progetto sono nei tabulati, §{§}.",
        "The largest force and the outcome of the ties in each analysis of the design state are in the tabulati, §{§}."}},
      {"tie.summary_worst", {"Verifica più sfavorevole", "Most unfavourable check"}},
      {"tie.summary_failing", {"Non verificate / verifiche", "Failing / checks"}},
      {"tie.summary_cap", {"Verifiche delle catene della parete: per ogni catena e stato la verifica con il D/C più alto (una non verificata prima di ogni verificata), il meccanismo che la governa e quante delle sue verifiche non sono soddisfatte.",
        "Checks of the wall's ties: for each tie and state the check with the highest D/C (a failing one before any satisfied one), the mechanism that governs it and how many of its checks fail."}},
      {"tie.in_tab", {"Le formule delle resistenze con le loro fonti, la verifica dinamica dopo l'intervento e i dettagli costruttivi delle catene di questo meccanismo sono nei tabulati, §{§}.",
        "The strength formulas with their sources, the dynamic check after the intervention and the detailing of this mechanism's ties are in the tabulati, §{§}."}},
      {"tie.intro_design",
       {"Stato di fatto: la parete come è, con le catene esistenti. Stato di progetto: con le catene progettate, la prima barra commerciale con il primo capochiave, nell'ordine documentato e preferendo le catene duttili, che soddisfano tutte le verifiche del meccanismo e di ogni catena, comprese quelle esistenti; una catena esistente che non è verificata è modificata con il minimo intervento (un nuovo capochiave, una nuova barra, la sua rimozione) (riparazione o intervento locale, NTC 2018 §8.4.1).",
        "Existing state: the wall as it is, with its existing ties. Design state: with the designed ties, the first commercial rod with the first anchor, in the documented order and preferring ductile ties, that satisfy every check of the mechanism and of every tie, the existing ones included; an existing tie that fails is changed by the least change (a new anchor, a new rod, its removal) (repair or local intervention, NTC 2018 §8.4.1)."}},
      {"tie.intro_given",
       {"Stato di fatto: la parete come è, con le catene esistenti. Stato di progetto: con le catene nuove indicate; "
        "verifiche del meccanismo e delle catene nei due stati.",
        "Existing state: the wall as it is, with its existing ties. Design state: with the new ties given; checks of "
        "the mechanism and of the ties in both states."}},
      {"tie.intro_existing",
       {"Le catene esistenti fanno parte dello stato di fatto: il meccanismo è verificato con esse e le loro verifiche "
        "sono quelle dello stato di fatto; non è previsto un intervento.",
        "The existing ties are part of the existing state: the mechanism is checked with them and their checks are "
        "those of the existing state; no intervention is given."}},
      {"tie.regime_ductile",
       {"Le catene progettate sono duttili: le estremità sono ringrossate o saldate e ogni resistenza fragile (filettatura, compressione locale, punzonamento, scorrimento, capochiave) supera la resistenza a snervamento della barra amplificata per la sovraresistenza; la barra può snervarsi senza rotture fragili fino al suo allungamento uniforme di progetto, e la capacità dello stato di progetto ne tiene conto.",
        "The designed ties are ductile: their ends are upset or welded and every brittle strength (thread, local compression, punching, sliding, anchor) exceeds the rod's yield strength amplified for overstrength; the rod may yield without a brittle failure up to its design uniform elongation, and the design state's capacity counts on it."}},
      {"tie.regime_elastic",
       {"Le catene progettate non sono duttili (la filettatura o la muratura cedono prima dello snervamento "
        "amplificato della barra): sono dimensionate per restare in campo elastico, e la forza massima che sviluppano "
        "nelle verifiche e in ogni analisi dinamica allo SLV resta al di sotto di ogni loro resistenza.",
        "The designed ties are not ductile (the thread or the masonry fail before the rod's amplified yield): they "
        "are sized to stay elastic, and the largest force they develop in the checks and in every SLV dynamic "
        "analysis stays below each of their strengths."}},
      {"tie.not_found",
       {"Nessuna combinazione degli elenchi, con il minimo intervento sulle catene esistenti non verificate, soddisfa tutte le verifiche; si riporta quella che vi si è avvicinata di più.",
        "No combination of the lists, with the least change to the existing ties that fail, satisfies every check; the one that came closest is shown."}},
      {"tie.wall_drawing",
       {"Le catene della parete sul meccanismo {} nello stato di progetto: per ogni livello la resistenza di progetto di una catena e quella dell'intero livello lungo la parete; ciascun meccanismo con le catene è disegnato nei tabulati.",
        "The wall's ties on the mechanism {} in the design state: for each level the design strength of one tie and of the whole level along the wall; each mechanism with the ties is drawn in the tabulati."}},
      {"tie.drawing",
       {"Le catene sul meccanismo nello stato considerato: per ogni livello la resistenza di progetto di una catena "
        "e quella dell'intero livello lungo la parete.",
        "The ties on the mechanism in the state shown: for each level the design strength of one tie and of the "
        "whole level along the wall."}},
      {"tie.drawing_label", {"T_Rd = {} kN/catena; {} kN/livello", "T_Rd = {} kN/tie; {} kN/level"}},
      {"tie.levels_title",
       {"Catene: materiali, estremità, capochiave e disposizione", "Ties: materials, ends, anchors and layout"}},
      {"tie.level", {"Livello", "Level"}},
      {"tie.state", {"Stato", "State"}},
      {"tie.existing", {"esistente", "existing"}},
      {"tie.new", {"nuova", "new"}},
      {"tie.rod", {"Barra", "Rod"}},
      {"tie.ends", {"Estremità", "Ends"}},
      {"tie.ends.threaded", {"filettate", "threaded"}},
      {"tie.ends.upset", {"ringrossate e filettate", "upset and threaded"}},
      {"tie.ends.welded", {"con barra filettata saldata", "with a welded threaded bar"}},
      {"tie.anchor", {"Capochiave", "Anchor"}},
      {"tie.plate", {"piastra", "plate"}},
      {"tie.bar", {"paletto", "bar"}},
      {"tie.layout", {"Disposizione", "Layout"}},
      {"tie.layout_n", {"{} catene su {} m di parete", "{} ties on {} m of wall"}},
      {"tie.layout_i", {"interasse {} m", "spacing {} m"}},
      {"tie.layout_e", {"distanza dalle estremità {} m", "edge distance {} m"}},
      {"tie.free_length", {"Lunghezza libera (m)", "Free length (m)"}},
      {"tie.pretension", {"Pretensione (kN)", "Pretension (kN)"}},
      {"tie.T_Rd_tie", {"T_Rd per catena (kN)", "T_Rd per tie (kN)"}},
      {"tie.T_Rd_level", {"T_Rd del livello (kN)", "T_Rd of the level (kN)"}},
      {"tie.behaviour", {"Comportamento", "Behaviour"}},
      {"tie.ductile", {"duttile", "ductile"}},
      {"tie.elastic", {"in campo elastico", "elastic"}},
      {"tie.component.rod", {"snervamento della barra", "rod yield"}},
      {"tie.component.thread", {"rottura della filettatura", "thread rupture"}},
      {"tie.component.bearing", {"compressione locale della muratura", "local compression of the masonry"}},
      {"tie.component.punching", {"punzonamento del cuneo murario", "punching of the masonry wedge"}},
      {"tie.component.anchor bending", {"flessione del capochiave", "bending of the anchor"}},
      {"tie.component.sliding",
       {"scorrimento della muratura sopra il capochiave", "sliding of the masonry above the anchor"}},
      {"tie.component.elongation", {"allungamento ultimo della barra", "ultimate elongation of the rod"}},
      // Formulas and their sources.
      {"tie.formulas_title", {"Resistenze: formule e fonti", "Strengths: formulas and sources"}},
      {"tie.f.rod",
       {"Snervamento della barra: N_pl,Rd = A_c f_yk / γ_M0, γ_M0 = 1,05 (NTC 2018 §4.2.4.1.2, [4.2.6]); f_yk, f_tk dalla Tab. 11.3.IX delle NTC 2018 per spessori fino a 40 mm; A_c è la sezione ridotta dal sovraspessore di corrosione δ su ogni faccia, A_c = π/4 (d − 2δ)² (EN 1993-5 §4.4).",
        "Rod yield: N_pl,Rd = A_c f_yk / γ_M0, γ_M0 = 1.05 (NTC 2018 §4.2.4.1.2, [4.2.6]); f_yk, f_tk from NTC 2018 Tab. 11.3.IX for thicknesses up to 40 mm; A_c is the section reduced by the corrosion allowance δ on every face, A_c = π/4 (d − 2δ)² (EN 1993-5 §4.4)."}},
      {"tie.f.thread",
       {"Rottura dell'estremità filettata, come bullone a trazione: N_t,Rd = 0,9 f_tk A_res,c / γ_M2, γ_M2 = 1,25 (NTC 2018 §4.2.8.1.1), con f_tk dell'acciaio della barra e A_res,c l'area resistente della filettatura metrica ISO (ISO 898-1) ridotta dal sovraspessore di corrosione.",
        "Rupture of the threaded end, as a bolt in tension: N_t,Rd = 0.9 f_tk A_res,c / γ_M2, γ_M2 = 1.25 (NTC 2018 §4.2.8.1.1), with f_tk of the rod's steel and A_res,c the stress area of the ISO metric thread (ISO 898-1) reduced by the corrosion allowance."}},
      {"tie.f.bearing",
       {"Compressione locale della muratura sotto il capochiave: N_c,Rd = f_d A_b, f_d = f_m / (FC γ_M), A_b area di "
        "appoggio (ipotesi del progettista, in appendice).",
        "Local compression of the masonry under the anchor: N_c,Rd = f_d A_b, f_d = f_m / (FC γ_M), A_b the bearing "
        "area (designer's assumption, in the appendix)."}},
      {"tie.f.punching",
       {"Punzonamento del cuneo murario: N_p,Rd = f_vd A_p, f_vd = τ / (FC γ_M); il cuneo si allarga a 45° dai bordi del capochiave nello spessore s della parete, e A_p è l'integrale sullo spessore del suo contorno laterale che giace nella muratura: il cuneo è tagliato dal coronamento della parete, dalle sue estremità, dalle aperture e dai cunei delle catene adiacenti (la mezzeria dell'interasse). Senza tagli A_p = s (2 (a + b) + 4 s); vale la catena del livello con A_p minore (ipotesi del progettista, in appendice).",
        "Punching of the masonry wedge: N_p,Rd = f_vd A_p, f_vd = τ / (FC γ_M); the wedge spreads at 45° from the anchor's edges through the wall's thickness s, and A_p is the integral over the thickness of its lateral boundary that lies in masonry: the wedge is cut by the wall's crown, its ends, its openings and the wedges of the adjacent ties (the middle of the spacing). Uncut, A_p = s (2 (a + b) + 4 s); the tie of the level with the smallest A_p governs (designer's assumption, in the appendix)."}},
      {"tie.f.sliding",
       {"Scorrimento della muratura sopra il capochiave sul giunto di malta al suo bordo inferiore: N_s,Rd = f_vd A_lat + (f_v0 / (FC γ_M) + μ σ_n / γ_M) A_base, con il blocco che si allarga a 45° nello spessore come il cuneo, i suoi fianchi dal giunto fino al coronamento (o alla prima apertura), σ_n il peso della muratura sovrastante più il carico sul coronamento, μ = 0,4 (NTC 2018 §4.5.6.1; Engineering Structures 2016: la resistenza è la minore fra lo scorrimento dei conci sui letti di malta e l'estrazione del cuneo).",
        "Sliding of the masonry above the anchor on the bed joint at its lower edge: N_s,Rd = f_vd A_sides + (f_v0 / (FC γ_M) + μ σ_n / γ_M) A_base, the block spreading at 45° through the thickness as the wedge does, its sides from the joint up to the crown (or the first opening), σ_n the weight of the masonry above plus the load on the crown, μ = 0.4 (NTC 2018 §4.5.6.1; Engineering Structures 2016: the strength is the smaller of the units sliding on the mortar beds and the wedge pulled out)."}},
      {"tie.f.temperature",
       {"Azione termica sulla barra vincolata agli estremi: N_T = E A α_T ΔT, α_T = 12·10⁻⁶/K, ΔT dato (di norma 15 K, NTC 2018 §3.5.5 Tab. 3.5.II, acciaio protetto); non si combina con il sisma (ψ2 = 0, NTC 2018 Tab. 2.5.I): barra e filettatura sono verificate nella combinazione fondamentale γ_P P0 + γ_Q N_T (γ_P = 1,0, γ_Q = 1,5), e la pretensione di una catena nuova P0 ≥ N_T assorbe l'escursione termica senza che la barra, scaldandosi, si allenti.",
        "Temperature action on the rod restrained at its ends: N_T = E A α_T ΔT, α_T = 12·10⁻⁶/K, ΔT given (15 K by default, NTC 2018 §3.5.5 Tab. 3.5.II, protected steel); it is not combined with the earthquake (ψ2 = 0, NTC 2018 Tab. 2.5.I): rod and thread are checked in the fundamental combination γ_P P0 + γ_Q N_T (γ_P = 1.0, γ_Q = 1.5), and a new tie's pretension P0 ≥ N_T takes up the temperature range so that the rod, warming, does not go slack."}},
      {"tie.f.plate",
       {"Flessione della piastra: strisce a mensola dai lati del dado sotto la pressione uniforme, N_b,Rd = 2 a b t² "
        "f_yk / (4 γ_M0 c²), c = (max(a, b) − s_dado) / 2 (ipotesi del progettista, in appendice).",
        "Bending of the plate: cantilever strips from the nut's flats under the uniform pressure, N_b,Rd = 2 a b t² "
        "f_yk / (4 γ_M0 c²), c = (max(a, b) − s_nut) / 2 (designer's assumption, in the appendix)."}},
      {"tie.f.bar",
       {"Flessione del paletto di lunghezza a e diametro b, caricato in mezzeria: N_b,Rd = 8 b³ f_yk / (6 γ_M0 a) "
        "(ipotesi del progettista, in appendice).",
        "Bending of a bar anchor of length a and diameter b, loaded at its middle: N_b,Rd = 8 b³ f_yk / (6 γ_M0 a) "
        "(designer's assumption, in the appendix)."}},
      {"tie.f.hierarchy",
       {"Gerarchia delle resistenze: la catena è duttile se le estremità sono ringrossate o saldate (una barra filettata su sé stessa si snerva solo nella filettatura) e ogni resistenza fragile (filettatura, compressione locale, punzonamento, scorrimento, capochiave) è almeno γ_Rd γ_ov A f_yk, con γ_ov = 1,25 (sovraresistenza dell'acciaio) e γ_Rd = 1,1 (EN 1998-1 §6.1.3 e §6.5.5; NTC 2018 §7.5.1); allora solo la barra si snerva.",
        "Capacity design: the tie is ductile if its ends are upset or welded (a rod threaded on itself yields only in its thread) and every brittle strength (thread, local compression, punching, sliding, anchor) is at least γ_Rd γ_ov A f_yk, with γ_ov = 1.25 (the steel's overstrength) and γ_Rd = 1.1 (EN 1998-1 §6.1.3 and §6.5.5; NTC 2018 §7.5.1); then only the rod yields."}},
      {"tie.f.elastic",
       {"Una catena non duttile deve restare in campo elastico: ogni sua resistenza è verificata con la forza massima "
        "che la catena sviluppa (nelle verifiche del meccanismo, allo spostamento di domanda e in ogni analisi "
        "dinamica); raggiungerla nell'analisi dinamica ne provoca la rottura, e la parete prosegue senza di essa.",
        "A tie that is not ductile must stay elastic: each of its strengths is checked with the largest force the tie "
        "develops (in the mechanism's checks, at the displacement demand and in every dynamic analysis); reaching it "
        "in a dynamic analysis breaks the tie, and the wall goes on without it."}},
      {"tie.f.elongation",
       {"Allungamento di una barra duttile: fino a ε_ud L, ε_ud = 0,9 ε_uk (NTC 2018 §4.1.2.1.2.3), con ε_uk l'allungamento uniforme (alla forza massima, prima della strizione) dell'acciaio: ε_uk = 15 f_yk / E per gli acciai S (EN 1993-1-1 §3.2.2: S235 1,68 %, S275 1,96 %, S355 2,54 %), (A_gt)k = 7,5 % per il B450C (NTC 2018 Tab. 11.3.Ib); la barra si snerva su tutta la lunghezza libera L tra le estremità più resistenti; oltre, si rompe. L'allungamento a rottura A della norma di prodotto comprende la strizione su una base corta e non è usato.",
        "Elongation of a ductile rod: up to ε_ud L, ε_ud = 0.9 ε_uk (NTC 2018 §4.1.2.1.2.3), with ε_uk the uniform elongation (at the maximum force, before necking) of the steel: ε_uk = 15 f_yk / E for the S grades (EN 1993-1-1 §3.2.2: S235 1.68 %, S275 1.96 %, S355 2.54 %), (A_gt)k = 7.5 % for B450C (NTC 2018 Tab. 11.3.Ib); the rod yields over its whole free length L between its stronger ends; beyond it, it breaks. The elongation after fracture A of the product standard includes the necking on a short gauge and is not used."}},
      {"tie.f.capacity",
       {"Capacità di ogni stato, com'è: la curva di capacità ha ogni catena elastica, una catena duttile snervata alla sua resistenza fino al suo allungamento ultimo, e ogni catena rotta dove cede (la duttile a ε_ud L, la non duttile alla sua resistenza), la curva proseguendo con le catene rimaste; d0 è dove essa si annulla. Lo spostamento ultimo (d_SLV, d_SLC, du*) è limitato alla prima rottura che riduce α di oltre il 50 %, come la crisi di un elemento (Circolare 2019 §C8.7.1.2.1.6). La stessa capacità vale nella verifica cinematica e in quella dinamica.",
        "Capacity of each state, as it is: the capacity curve has each tie elastic, a ductile tie yielded at its strength up to its ultimate elongation, and every tie broken where it fails (a ductile one at ε_ud L, one that is not ductile at its strength), the curve going on with the ties left; d0 is where it vanishes. The ultimate displacement (d_SLV, d_SLC, du*) is limited to the first break that drops α by more than 50 %, as the failure of an element (Circolare 2019 §C8.7.1.2.1.6). The same capacity serves the kinematic and the dynamic check."}},
      {"tie.f.layout",
       {"Disposizione: n catene su una parete lunga L (interasse e distanza dalle estremità indicati); l'analisi per metro di parete usa n / L catene al metro; ogni capochiave giace nella parete (sotto il coronamento, entro le estremità, fuori dalle aperture, separato dai vicini).",
        "Layout: n ties on a wall of length L (spacing and edge distance given); the analysis per metre of wall uses n / L ties per metre; every anchor lies within the wall (below its crown, within its ends, off its openings, apart from its neighbours)."}},
      {"tie.f.note",
       {"Le grandezze, i valori assunti e la loro base sono elencati in appendice (Ipotesi e letture adottate).",
        "The quantities, the values adopted and their basis are listed in the appendix (assumptions and readings "
        "adopted)."}},
      // Checks.
      {"tie.checks_title", {"Verifiche della catena", "Checks of the tie"}},
      {"tie.state_before", {"stato di fatto", "existing state"}},
      {"tie.state_after", {"stato di progetto", "design state"}},
      {"tie.ductile_text",
       {"Catena duttile: ogni resistenza fragile supera γ_Rd γ_ov A f_yk = {} kN (la minore, {}, vale {} kN); la barra può snervarsi fino all'allungamento ε_ud L = {} mm.",
        "Ductile tie: every brittle strength exceeds γ_Rd γ_ov A f_yk = {} kN (the smallest, {}, is {} kN); the rod may yield up to the elongation ε_ud L = {} mm."}},
      {"tie.elastic_text",
       {"Catena non duttile ({} = {} kN < γ_Rd γ_ov A f_yk = {} kN): deve restare in campo elastico; ogni sua "
        "resistenza è verificata con la forza massima che sviluppa, {} kN.",
        "Tie not ductile ({} = {} kN < γ_Rd γ_ov A f_yk = {} kN): it must stay elastic; each of its strengths is "
        "checked with the largest force it develops, {} kN."}},
      {"tie.elastic_text_threaded",
       {"Catena non duttile (estremità filettate sulla barra: la filettatura, {} kN, è più debole della barra): deve restare in campo elastico; ogni sua resistenza è verificata con la forza massima che sviluppa, {} kN.",
        "Tie not ductile (ends threaded on the rod: the thread, {} kN, is weaker than the rod): it must stay elastic; each of its strengths is checked with the largest force it develops, {} kN."}},
      {"tie.demand_static",
       {"Forza massima richiesta dalle verifiche del meccanismo: {} kN per catena",
        "Largest force the mechanism's checks need: {} kN per tie"}},
      {"tie.demand_curve",
       {"forza allo spostamento di domanda: {} kN", "force at the displacement demand: {} kN"}},
      {"tie.demand_dynamic",
       {"forza massima nelle analisi dinamiche: {} kN ({} analisi)",
        "largest force in the dynamic analyses: {} kN ({} analyses)"}},
      {"tie.demand_broken",
       {"rottura in {} analisi su {} ({})", "broken in {} analyses of {} ({})"}},
      {"tie.check", {"Verifica", "Check"}},
      {"tie.clause", {"Riferimento", "Clause / source"}},
      {"tie.demand", {"Domanda", "Demand"}},
      {"tie.capacity", {"Capacità", "Capacity"}},
      {"tie.unit", {"Unità", "Unit"}},
      {"tie.unit_analyses", {"analisi", "analyses"}},
      {"tie.outcome", {"Esito", "Outcome"}},
      {"tie.ok", {"verificato", "satisfied"}},
      {"tie.ko", {"non verificato", "not satisfied"}},
      {"tie.unreachable", {"non raggiungibile", "not reachable"}},
      {"tie.unreachable_why",
       {"nessuna forza fino a 100 volte il peso del meccanismo soddisfa la verifica",
        "no force up to 100 times the mechanism's weight satisfies the check"}},
      {"tie.check.rod yield", {"snervamento della barra", "rod yield"}},
      {"tie.check.thread", {"rottura della filettatura", "thread rupture"}},
      {"tie.check.local compression", {"compressione locale della muratura", "local compression of the masonry"}},
      {"tie.check.punching", {"punzonamento del cuneo murario", "punching of the masonry wedge"}},
      {"tie.check.anchor bending", {"flessione del capochiave", "bending of the anchor"}},
      {"tie.check.sliding", {"scorrimento della muratura sopra il capochiave", "sliding of the masonry above the anchor"}},
      {"tie.check.hierarchy sliding", {"gerarchia: scorrimento", "capacity design: sliding"}},
      {"tie.check.temperature rod", {"azione termica: barra", "temperature action: rod"}},
      {"tie.check.temperature thread", {"azione termica: filettatura", "temperature action: thread"}},
      {"tie.check.pretension",
       {"pretensione contro l'escursione termica", "pretension against the temperature range"}},
      {"tie.check.hierarchy thread", {"gerarchia: filettatura", "capacity design: thread"}},
      {"tie.check.hierarchy local compression",
       {"gerarchia: compressione locale", "capacity design: local compression"}},
      {"tie.check.hierarchy punching", {"gerarchia: punzonamento", "capacity design: punching"}},
      {"tie.check.hierarchy anchor bending", {"gerarchia: capochiave", "capacity design: anchor"}},
      {"tie.check.rod elongation", {"allungamento della barra", "rod elongation"}},
      {"tie.check.cone spacing", {"interasse dei cunei di punzonamento", "spacing of the punching wedges"}},
      {"tie.check.edge distance", {"distanza dalle estremità della parete", "distance from the wall's ends"}},
      {"tie.check.required force", {"forza richiesta dal meccanismo", "force the mechanism needs"}},
      {"tie.check.dynamic rupture", {"rottura nelle analisi dinamiche", "rupture in the dynamic analyses"}},
      {"tie.clause.rod yield", {"NTC 2018 §4.2.4.1.2 [4.2.6]", "NTC 2018 §4.2.4.1.2 [4.2.6]"}},
      {"tie.clause.thread", {"NTC 2018 §4.2.8.1.1", "NTC 2018 §4.2.8.1.1"}},
      {"tie.clause.local compression", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.punching", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.anchor bending", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.sliding", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.hierarchy sliding", {"EN 1998-1 §6.5.5; NTC 2018 §7.5.1", "EN 1998-1 §6.5.5; NTC 2018 §7.5.1"}},
      {"tie.clause.temperature rod", {"NTC 2018 §3.5.5, §2.5.3", "NTC 2018 §3.5.5, §2.5.3"}},
      {"tie.clause.temperature thread", {"NTC 2018 §3.5.5, §2.5.3", "NTC 2018 §3.5.5, §2.5.3"}},
      {"tie.clause.pretension", {"NTC 2018 §3.5.5", "NTC 2018 §3.5.5"}},
      {"tie.clause.hierarchy thread", {"EN 1998-1 §6.5.5; NTC 2018 §7.5.1", "EN 1998-1 §6.5.5; NTC 2018 §7.5.1"}},
      {"tie.clause.hierarchy local compression",
       {"EN 1998-1 §6.5.5; NTC 2018 §7.5.1", "EN 1998-1 §6.5.5; NTC 2018 §7.5.1"}},
      {"tie.clause.hierarchy punching", {"EN 1998-1 §6.5.5; NTC 2018 §7.5.1", "EN 1998-1 §6.5.5; NTC 2018 §7.5.1"}},
      {"tie.clause.hierarchy anchor bending",
       {"EN 1998-1 §6.5.5; NTC 2018 §7.5.1", "EN 1998-1 §6.5.5; NTC 2018 §7.5.1"}},
      {"tie.clause.rod elongation",
       {"NTC 2018 §4.1.2.1.2.3, EN 1993-1-1 §3.2.2", "NTC 2018 §4.1.2.1.2.3, EN 1993-1-1 §3.2.2"}},
      {"tie.clause.cone spacing", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.edge distance", {"ipotesi del progettista", "designer's assumption"}},
      {"tie.clause.dynamic rupture", {"Circolare 2019 C8.7.1.2.1.9", "Circolare 2019 C8.7.1.2.1.9"}},
      {"tie.required_title",
       {"Forza necessaria per ogni verifica del meccanismo", "Force needed by each check of the mechanism"}},
      {"tie.code", {"Norma", "Code"}},
      {"tie.ls", {"SL", "LS"}},
      {"tie.kind", {"Tipo", "Kind"}},
      {"tie.where", {"Posizione", "Location"}},
      {"tie.per_tie", {"per catena (kN)", "per tie (kN)"}},
      {"tie.per_level", {"per livello (kN)", "per level (kN)"}},
      {"tie.per_metre", {"per metro (kN/m)", "per metre (kN/m)"}},
      {"tie.dc_without", {"D/C senza il livello", "D/C without the level"}},
      {"tie.kind.strength", {"resistenza", "strength"}},
      {"tie.kind.displacement", {"spostamento", "displacement"}},
      {"tie.where.ground", {"al suolo", "ground"}},
      {"tie.where.height", {"in quota", "height"}},
      // The two states.
      {"tie.before_after",
       {"Il meccanismo nello stato di fatto e nello stato di progetto",
        "The mechanism in the existing and in the design state"}},
      {"tie.before", {"stato di fatto", "existing state"}},
      {"tie.after", {"stato di progetto", "design state"}},
      {"tie.d_tie",
       {"d* per cui la prima catena raggiunge la resistenza (m)", "d* at which the first tie reaches its strength (m)"}},
      {"tie.d_cap",
       {"d* della prima rottura che riduce α di oltre il 50 % (m)",
        "d* of the first break that drops α by more than 50 % (m)"}},
      {"tie.zeta", {"ζE = PGA capacità / PGA domanda (NTC 2018)", "ζE = PGA capacity / PGA demand (NTC 2018)"}},
      {"tie.all_checks", {"tutte le verifiche", "every check"}},
      {"tie.capacity_note",
       {"Ogni stato è calcolato com'è: le catene si rompono dove cedono e la parete prosegue con quelle rimaste; gli spostamenti adottati si fermano alla prima rottura che riduce il moltiplicatore α di oltre il 50 %, e sono gli stessi nella verifica dinamica.",
        "Each state is computed as it is: the ties break where they fail and the wall goes on with those left; the adopted displacements stop at the first break that drops the multiplier α by more than 50 %, and are the same in the dynamic check."}},
      // Dynamics.
      {"tie.dyn_title",
       {"Verifica dinamica nello stato di fatto e nello stato di progetto (Circolare 2019 C8.7.1.2.1.9)",
        "Dynamic check in the existing and in the design state (Circolare 2019 C8.7.1.2.1.9)"}},
      {"tie.dyn_intro",
       {"Le analisi dinamiche della facciata (sopra) sono quelle dello stato di fatto; sono ripetute con tutte le "
        "catene dello stato di progetto, ciascun livello vincolo monolatero (solo trazione): una catena duttile si "
        "snerva e si rompe all'allungamento ultimo, una non duttile si rompe quando la sua forza raggiunge la "
        "resistenza, e da quel momento la parete prosegue senza di essa. Una rottura è una crisi dell'intervento.",
        "The façade's dynamic analyses (above) are those of the existing state; they are repeated with every tie of "
        "the design state, each level a one-sided (tension-only) restraint: a ductile tie yields and breaks at its "
        "ultimate elongation, one that is not ductile breaks when its force reaches its strength, and from then on "
        "the wall goes on without it. A rupture is a failure of the intervention."}},
      {"tie.dyn_intro_wall",
       {"Le analisi dinamiche di ciascun meccanismo nella sua sezione sono quelle dello stato di fatto; sono ripetute "
        "con tutte le catene dello stato di progetto, ciascun livello vincolo monolatero (solo trazione): una catena "
        "duttile si snerva e si rompe all'allungamento ultimo, una non duttile si rompe quando la sua forza raggiunge "
        "la resistenza, e da quel momento la parete prosegue senza di essa. Una rottura è una crisi dell'intervento.",
        "Each mechanism's dynamic analyses in its section are those of the existing state; they are repeated with "
        "every tie of the design state, each level a one-sided (tension-only) restraint: a ductile tie yields and "
        "breaks at its ultimate elongation, one that is not ductile breaks when its force reaches its strength, and "
        "from then on the wall goes on without it. A rupture is a failure of the intervention."}},
      {"tie.dyn_intro_existing_wall",
       {"Le analisi dinamiche di ciascun meccanismo nella sua sezione sono quelle della parete con le catene esistenti, "
        "vincoli monolateri con la loro duttilità e le loro rotture.",
        "Each mechanism's dynamic analyses in its section are those of the wall with its existing ties, one-sided "
        "restraints with their ductility and ruptures."}},
      {"tie.dyn_intro_existing",
       {"Le analisi dinamiche della facciata (sopra) sono quelle della parete con le catene esistenti, vincoli "
        "monolateri con la loro duttilità e le loro rotture.",
        "The façade's dynamic analyses (above) are those of the wall with its existing ties, one-sided restraints "
        "with their ductility and ruptures."}},
      {"tie.dyn_not",
       {"Analisi dinamica con le catene non eseguita: richiede la sezione dinamica e un moto monolatero (corpo o "
        "catena cinematica).",
        "Dynamic analysis with the ties not done: it needs the dynamic section and one-sided rocking (a body or a "
        "chain)."}},
      {"tie.dyn_e", {"e (restituzione)", "e (restitution)"}},
      {"tie.dyn_N", {"N accelerogrammi", "N records"}},
      {"tie.dyn_state", {"Stato", "State"}},
      {"tie.dyn_over", {"Ribaltamenti", "Overturned"}},
      {"tie.dyn_d", {"d* domanda (m)", "d* demand (m)"}},
      {"tie.dyn_yield", {"Analisi con snervamento", "Analyses with yielding"}},
      {"tie.dyn_broken", {"Analisi con rottura", "Analyses with a rupture"}},
      {"tie.dyn_verdict", {"Esito", "Outcome"}},
      {"tie.dyn_runs_intro",
       {"Ogni analisi dello stato di progetto: la forza massima di una catena e l'esito delle catene (in campo "
        "elastico, snervata se duttile, rotta e per quale componente).",
        "Each analysis of the design state: the largest force of one tie and the outcome of the ties (elastic, "
        "yielded if ductile, broken and by which component)."}},
      {"tie.dyn_record", {"accelerogramma", "record"}},
      {"tie.dyn_polarity", {"verso", "polarity"}},
      {"tie.normal", {"diretto", "normal"}},
      {"tie.reversed", {"invertito", "reversed"}},
      {"tie.dyn_fmax", {"F max per catena (kN)", "F max per tie (kN)"}},
      {"tie.dyn_outcome", {"esito delle catene", "outcome of the ties"}},
      {"tie.run_elastic", {"in campo elastico", "elastic"}},
      {"tie.run_yielded", {"snervata, allungamento permanente {} mm", "yielded, permanent elongation {} mm"}},
      {"tie.run_broken", {"ROTTURA: {}, {}, a t = {} s", "RUPTURE: {}, {}, at t = {} s"}},
      {"tie.run_failed", {"integrazione non completata", "integration not completed"}},
      // Detailing.
      {"tie.det_title", {"Dettagli costruttivi", "Detailing"}},
      {"tie.det_anchor", {"capochiave: {}; {}.", "anchor: {}; {}."}},
      {"tie.det_plate",
       {"piastra piana con foro centrale di diametro pari alla filettatura più 2 mm, posata su un letto di malta di "
        "calce che ne regolarizza l'appoggio",
        "a flat plate with a central hole of the thread's diameter plus 2 mm, laid on a bed of lime mortar that "
        "evens its bearing"}},
      {"tie.det_bar",
       {"paletto infilato nell'occhiello della barra, in battuta sulla muratura per tutta la lunghezza",
        "a bar through the rod's eye, bearing on the masonry over its whole length"}},
      {"tie.det_nut",
       {"Dado esagonale ISO 4032 M{} (chiave {} mm, altezza {} mm) di classe adeguata all'acciaio della barra, con "
        "rondella ISO 7089 (diametro × spessore {} mm) e controdado.",
        "Hexagon nut ISO 4032 M{} (across flats {} mm, height {} mm) of a class matched to the rod's steel, with an "
        "ISO 7089 washer (diameter × thickness {} mm) and a lock nut."}},
      {"tie.det_ends.threaded",
       {"Estremità filettate sulla barra stessa: la sezione resistente è quella della filettatura.",
        "Ends threaded on the rod itself: the resisting section is the thread's."}},
      {"tie.det_ends.upset",
       {"Estremità ringrossate a caldo e poi filettate: la filettatura ha sezione maggiore della barra.",
        "Ends hot-upset and then threaded: the thread's section is larger than the rod's."}},
      {"tie.det_ends.welded",
       {"Estremità con barra filettata di diametro maggiore saldata di testa a piena penetrazione (saldatura a "
        "completo ripristino).",
        "Ends with a threaded bar of larger diameter butt-welded with full penetration (full-strength weld)."}},
      {"tie.det_layout", {"Disposizione: {}.", "Layout: {}."}},
      {"tie.det_pretension",
       {"Pretensione {} kN per catena ({} % della resistenza di progetto), applicata serrando il dado con chiave "
        "dinamometrica o con tenditore, e controllata a fine serraggio.",
        "Pretension {} kN per tie ({} % of the design strength), applied by tightening the nut with a torque wrench "
        "or a turnbuckle, and checked at the end of tightening."}},
      {"tie.det_pretension_none",
       {"Nessuna pretensione di calcolo: il dado è serrato a mano fino al contatto, per eliminare i giochi senza "
        "indurre trazione.",
        "No design pretension: the nut is tightened by hand to contact, to take up the slack without inducing "
        "tension."}},
      {"tie.det_far_end",
       {"Ancoraggio all'estremo opposto: un capochiave uguale su una parete di resistenza almeno pari, sottoposta "
        "alle stesse verifiche; il calcolo assume fisso l'estremo opposto (la rigidezza E A / L della barra è "
        "quella dell'intera lunghezza libera).",
        "Anchorage at the far end: an identical anchor on a wall of at least the same strength, subject to the same "
        "checks; the analysis takes the far end as fixed (the rod's stiffness E A / L is that of its whole free "
        "length)."}},
      {"tie.det_corrosion",
       {"Protezione dalla corrosione: zincatura a caldo di barra, piastre, dadi e rondelle (UNI EN ISO 1461) o ciclo di "
        "verniciatura per la classe di esposizione del sito (UNI EN ISO 12944); filettature protette, foro nella "
        "muratura sigillato con malta di calce.",
        "Corrosion protection: hot-dip galvanizing of rod, plates, nuts and washers (EN ISO 1461) or a paint system "
        "for the site's exposure class (EN ISO 12944); threads protected, the hole in the masonry sealed with lime "
        "mortar."}},
      {"tie.det_execution",
       {"Esecuzione: foro a rotazione senza percussione, barra posata in quota e in asse, verifica della "
        "corrispondenza delle murature d'appoggio ai valori assunti (f_m, τ, spessore) prima della posa.",
        "Execution: holes drilled by rotation without percussion, the rod laid at its level and axis, and the bearing "
        "masonry checked against the values assumed (f_m, τ, thickness) before laying."}},
      // The building's two states (building_html.cpp).
      {"tie.bld.cap_before",
       {"Stato di fatto: ogni meccanismo con le sue catene esistenti; ζE = PGA_C/PGA_D (NTC 2018, approccio del "
        "metodo adottato), l'esito di tutte le verifiche cinematiche e di quelle delle catene esistenti, la verifica "
        "dinamica.",
        "Existing state: each mechanism with its existing ties; ζE = PGA_C/PGA_D (NTC 2018, the adopted method's "
        "approach), whether every kinematic check and every check of the existing ties is satisfied, the dynamic "
        "check."}},
      {"tie.bld.cap_after",
       {"Stato di progetto: ogni meccanismo con le catene esistenti e quelle nuove (assegnate o progettate); le "
        "stesse grandezze.",
        "Design state: each mechanism with its existing and new ties (given or designed); the same quantities."}},
      {"tie.bld.ties_before", {"Catene esistenti", "Existing ties"}},
      {"tie.bld.ties_after", {"Catene esistenti e nuove", "Existing and new ties"}},
      {"tie.bld.index_before",
       {"Indicatore di rischio dell'edificio nello stato di fatto (il più piccolo ζE dei suoi meccanismi): {} ({}); "
        "meccanismi con tutte le verifiche soddisfatte: {} su {}.",
        "Safety index of the building in the existing state (the smallest ζE of its mechanisms): {} ({}); mechanisms "
        "with every check satisfied: {} of {}."}},
      {"tie.bld.index_after",
       {"Indicatore di rischio dell'edificio nello stato di progetto: {} ({}); meccanismi con tutte le verifiche "
        "soddisfatte: {} su {}.",
        "Safety index of the building in the design state: {} ({}); mechanisms with every check satisfied: {} of {}."}},
      // Readings adopted (for the appendix): quantity, reading, basis with its certainty.
      {"tie.reading.1.q", {"Resistenze dell'acciaio f_yk, f_tk", "Steel strengths f_yk, f_tk"}},
      {"tie.reading.1.r",
       {"S235 235/360, S275 275/430, S355 355/510 MPa (spessori fino a 40 mm)",
        "S235 235/360, S275 275/430, S355 355/510 MPa (thicknesses up to 40 mm)"}},
      {"tie.reading.1.b",
       {"NTC 2018 Tab. 11.3.IX [R]; la EN 10025-2 Tab. 7 dà f_tk minori per 3 < t ≤ 100 mm (S275 410, S355 470 MPa) "
        "[V-S]: adottati i valori delle NTC",
        "NTC 2018 Tab. 11.3.IX [R]; EN 10025-2 Tab. 7 gives lower f_tk for 3 < t ≤ 100 mm (S275 410, S355 470 MPa) "
        "[V-S]: the NTC values are adopted"}},
      {"tie.reading.2.q", {"Coefficienti parziali dell'acciaio", "Partial factors of steel"}},
      {"tie.reading.2.r", {"γ_M0 = 1,05; γ_M2 = 1,25", "γ_M0 = 1.05; γ_M2 = 1.25"}},
      {"tie.reading.2.b", {"NTC 2018 §4.2.4.1.1, Tab. 4.2.VII e 4.2.XII [R]", "NTC 2018 §4.2.4.1.1, Tab. 4.2.VII and 4.2.XII [R]"}},
      {"tie.reading.3.q", {"Estremità filettata", "Threaded end"}},
      {"tie.reading.3.r",
       {"verificata come bullone a trazione, 0,9 f_tk A_res / γ_M2, con f_tk dell'acciaio della barra; A_res dalla "
        "tabella ISO (M16 157, M20 245 mm²)",
        "checked as a bolt in tension, 0.9 f_tk A_res / γ_M2, with f_tk of the rod's steel; A_res from the ISO table "
        "(M16 157, M20 245 mm²)"}},
      {"tie.reading.3.b",
       {"NTC 2018 §4.2.8.1.1 [R]; f_tk della barra al posto di f_tb [I]; ISO 898-1 Tab. 4, controllata con "
        "A_res = π/4 (d − 0,9382 P)² [R]",
        "NTC 2018 §4.2.8.1.1 [R]; the rod's f_tk for f_tb [I]; ISO 898-1 Tab. 4, checked against "
        "A_res = π/4 (d − 0.9382 P)² [R]"}},
      {"tie.reading.4.q", {"Gerarchia delle resistenze", "Capacity design"}},
      {"tie.reading.4.r",
       {"resistenze fragili ≥ γ_Rd γ_ov A f_yk con γ_Rd = 1,1 e γ_ov = 1,25", "brittle strengths ≥ γ_Rd γ_ov A f_yk "
        "with γ_Rd = 1.1 and γ_ov = 1.25"}},
      {"tie.reading.4.b",
       {"EN 1998-1 §6.5.5(3) e §6.1.3(2) [R]; NTC 2008 §7.5.1 γ_ov = 1,25 [R]; NTC 2018 Tab. 7.5.I dà valori per "
        "classe d'acciaio non superiori a 1,20 [R]: adottato il maggiore [I]",
        "EN 1998-1 §6.5.5(3) and §6.1.3(2) [R]; NTC 2008 §7.5.1 γ_ov = 1.25 [R]; NTC 2018 Tab. 7.5.I gives values per "
        "steel grade not above 1.20 [R]: the larger is adopted [I]"}},
      {"tie.reading.5.q", {"Allungamento di progetto di una barra duttile", "Design elongation of a ductile rod"}},
      {"tie.reading.5.r",
       {"ε_ud = 0,9 ε_uk, ε_uk allungamento uniforme: 15 f_yk / E per gli acciai S (S235 1,68 %, S275 1,96 %, S355 2,54 %), (A_gt)k = 7,5 % per il B450C; su tutta la lunghezza libera per estremità ringrossate o saldate; nessuno per estremità filettate sulla barra",
        "ε_ud = 0.9 ε_uk, ε_uk the uniform elongation: 15 f_yk / E for the S grades (S235 1.68 %, S275 1.96 %, S355 2.54 %), (A_gt)k = 7.5 % for B450C; over the whole free length with upset or welded ends; none with ends threaded on the rod"}},
      {"tie.reading.5.b",
       {"EN 1993-1-1 §3.2.2(1), ε_u ≥ 15 ε_y, valore raccomandato [R]; NTC 2018 Tab. 11.3.Ib [R]; il fattore 0,9 come in NTC 2018 §4.1.2.1.2.3 [R/I]; la EN 10025-2 dà solo l'allungamento a rottura A, che comprende la strizione: non usato [I]",
        "EN 1993-1-1 §3.2.2(1), ε_u ≥ 15 ε_y, recommended value [R]; NTC 2018 Tab. 11.3.Ib [R]; the factor 0.9 as in NTC 2018 §4.1.2.1.2.3 [R/I]; EN 10025-2 gives only the elongation after fracture A, which includes the necking: not used [I]"}},
      {"tie.reading.6.q", {"Compressione locale della muratura", "Local compression of the masonry"}},
      {"tie.reading.6.r",
       {"f_d A_b, f_d = f_m / (FC γ_M), γ_M = 2, senza incremento per carico concentrato (β = 1)",
        "f_d A_b, f_d = f_m / (FC γ_M), γ_M = 2, with no increase for a concentrated load (β = 1)"}},
      {"tie.reading.6.b",
       {"prassi [R]; γ_M = 2 dal limite inferiore di NTC 2018 Tab. 4.5.II [R/I]; EN 1996-1-1 §6.1.3 e NTC 2018 "
        "§4.5.6.2 ammettono β ≥ 1 [R]: β = 1 [I]",
        "practice [R]; γ_M = 2 from the lower end of NTC 2018 Tab. 4.5.II [R/I]; EN 1996-1-1 §6.1.3 and NTC 2018 "
        "§4.5.6.2 allow β ≥ 1 [R]: β = 1 [I]"}},
      {"tie.reading.7.q", {"Punzonamento della muratura", "Punching of the masonry"}},
      {"tie.reading.7.r",
       {"cuneo a 45° dai bordi del capochiave nello spessore della parete, τ sul suo contorno laterale nella muratura, integrato sullo spessore: tagliato dal coronamento, dalle estremità, dalle aperture e dai cunei adiacenti (mezzeria dell'interasse); l'estremità della parete come bordo libero",
        "a wedge at 45° from the anchor's edges through the wall's thickness, τ on its lateral boundary in masonry, integrated over the thickness: cut by the crown, the ends, the openings and the adjacent wedges (the middle of the spacing); the wall's end as a free edge"}},
      {"tie.reading.7.b",
       {"prassi [R]; letteratura: Engineering Structures 2016, capacità delle piastre di ancoraggio su muratura (cono troncato o scorrimento dei conci, letto il solo sommario) [V-S]; DTU R-134, 2006 (punzonamento e scorrimento a un bordo parallelo ai letti, letto il sommario) [V-S]; nessuna formula di norma trovata (Linee guida 2011 per i beni culturali, CNR-DT 212/2013: testo non trovato) [I]; il taglio del cuneo da parte della parete [I]",
        "practice [R]; literature: Engineering Structures 2016, load-carrying capacity of anchor plates on masonry (truncated cone or sliding of the units, abstract only) [V-S]; DTU R-134, 2006 (punching, and sliding at an edge parallel to the bed joints, abstract read) [V-S]; no code formula found (Guidelines 2011 for cultural heritage, CNR-DT 212/2013: text not found) [I]; the wedge cut by the wall [I]"}},
      {"tie.reading.8.q", {"Flessione del capochiave", "Bending of the anchor"}},
      {"tie.reading.8.r",
       {"piastra: strisce a mensola dai lati del dado (larghezza in chiave ISO 4032); paletto: trave appoggiata "
        "caricata in mezzeria",
        "plate: cantilever strips from the nut's flats (ISO 4032 width across flats); bar: a simply supported beam "
        "loaded at its middle"}},
      {"tie.reading.8.b",
       {"modello del progettista [I]; una piastra non più larga del dado è rifiutata",
        "designer's model [I]; a plate no wider than its nut is refused"}},
      {"tie.reading.9.q", {"Estremo opposto della catena", "Far end of the tie"}},
      {"tie.reading.9.r", {"fisso; rigidezza E A / L sull'intera lunghezza libera", "fixed; stiffness E A / L over the whole free length"}},
      {"tie.reading.9.b", {"ipotesi del progettista [I]", "designer's assumption [I]"}},
      {"tie.reading.10.q", {"Capacità dopo l'intervento", "Capacity after the intervention"}},
      {"tie.reading.10.r",
       {"la curva della parete com'è: catene elastiche, duttili snervate fino a ε_ud L, ciascuna rotta dove cede; spostamenti ultimi limitati alla prima rottura che riduce α di oltre il 50 %; la stessa capacità nella verifica dinamica",
        "the curve of the wall as it is: ties elastic, ductile ones yielded up to ε_ud L, each broken where it fails; ultimate displacements limited at the first break that drops α by more than 50 %; the same capacity in the dynamic check"}},
      {"tie.reading.10.b",
       {"Circolare 2019 §C8.7.1.2.1.6: d_SLV al 40 % di d0 sulla curva con le sole forze sicuramente presenti fino al collasso, e non oltre lo spostamento per cui un elemento cede con una riduzione di capacità superiore al 50 % [V-T]; la rottura di una catena come tale elemento, la riduzione misurata su α [I]",
        "Circolare 2019 §C8.7.1.2.1.6: d_SLV at 40 % of d0 on the curve with only the forces surely present up to collapse, and not beyond the displacement at which an element fails with a capacity drop above 50 % [V-T]; the break of a tie as that element, the drop measured on α [I]"}},
      {"tie.reading.11.q", {"Catena nel moltiplicatore α0", "Tie in the multiplier α0"}},
      {"tie.reading.11.r",
       {"ogni livello alla sua resistenza di progetto T_Rd nel lavoro virtuale", "each level at its design strength "
        "T_Rd in the virtual work"}},
      {"tie.reading.11.b", {"prassi dell'analisi cinematica (C8A.4, C8.7.1) [R]", "practice of the kinematic analysis (C8A.4, C8.7.1) [R]"}},
      {"tie.reading.12.q", {"Catena nell'analisi dinamica", "Tie in the dynamic analysis"}},
      {"tie.reading.12.r",
       {"vincolo monolatero elastico; una catena duttile si snerva alla resistenza della barra e si rompe a ε_ud L, "
        "una non duttile si rompe alla sua resistenza; la forza persa, la parete prosegue senza il livello",
        "one-sided elastic restraint; a ductile tie yields at the rod's strength and breaks at ε_ud L, one that is "
        "not ductile breaks at its strength; its force lost, the wall goes on without the level"}},
      {"tie.reading.12.b", {"modello del progettista [I]", "designer's model [I]"}},
      {"tie.reading.13.q", {"Disposizione lungo la parete", "Layout along the wall"}},
      {"tie.reading.13.r",
       {"numero intero di catene, analisi per metro con n / L catene al metro; ogni capochiave nella parete, i cunei tagliati dai vicini",
        "an integer number of ties, analysis per metre with n / L ties per metre; every anchor within the wall, the wedges cut by their neighbours"}},
      {"tie.reading.13.b", {"ipotesi del progettista [I]", "designer's assumption [I]"}},
      {"tie.reading.14.q", {"Diametro minimo della barra di progetto", "Smallest designed rod"}},
      {"tie.reading.14.r", {"16 mm, modificabile nel file del caso", "16 mm, editable in the case file"}},
      {"tie.reading.14.b", {"prassi per catene in muratura storica [I]", "practice for ties in historic masonry [I]"}},
      {"tie.reading.15.q", {"Scorrimento sopra il capochiave", "Sliding above the anchor"}},
      {"tie.reading.15.r",
       {"blocco sopra il bordo inferiore del capochiave, sul giunto orizzontale: f_vd sui fianchi, f_v0 / (FC γ_M) + μ σ_n / γ_M alla base; f_v0 = τ se non dato, μ = 0,4; σ_n dal peso della muratura sovrastante e dal carico sul coronamento (0 se non dato)",
        "the block above the anchor's lower edge, on the horizontal joint: f_vd on its sides, f_v0 / (FC γ_M) + μ σ_n / γ_M on its base; f_v0 = τ unless given, μ = 0.4; σ_n from the weight of the masonry above and the load on the crown (0 unless given)"}},
      {"tie.reading.15.b",
       {"Engineering Structures 2016 (scorrimento dei conci sui letti di malta, sommario) [V-S]; NTC 2018 §4.5.6.1, f_vk = f_vk0 + 0,4 σ_n [R]; Circolare 2019 Tab. C8.5.I dà f_v0 solo per murature regolari [R]: f_v0 = τ [I]",
        "Engineering Structures 2016 (units sliding on the mortar beds, abstract) [V-S]; NTC 2018 §4.5.6.1, f_vk = f_vk0 + 0.4 σ_n [R]; Circolare 2019 Tab. C8.5.I gives f_v0 only for regular masonry [R]: f_v0 = τ [I]"}},
      {"tie.reading.16.q", {"Azione termica sulla barra", "Temperature action on the rod"}},
      {"tie.reading.16.r",
       {"N_T = E A α_T ΔT, ΔT = 15 K se non dato, α_T = 12·10⁻⁶/K; combinazione fondamentale γ_P P0 + 1,5 N_T su barra e filettatura, non combinata con il sisma; pretensione di una catena nuova ≥ N_T",
        "N_T = E A α_T ΔT, ΔT = 15 K unless given, α_T = 12·10⁻⁶/K; fundamental combination γ_P P0 + 1.5 N_T on rod and thread, not combined with the earthquake; a new tie's pretension ≥ N_T"}},
      {"tie.reading.16.b",
       {"NTC 2018 §3.5.5 Tab. 3.5.II (acciaio protetto ±15 °C), §3.5.7 Tab. 3.5.III (α_T), Tab. 2.5.I (ψ2 = 0), Tab. 2.6.I (γ_Q = 1,5) [R]; vincolo rigido agli estremi [I]",
        "NTC 2018 §3.5.5 Tab. 3.5.II (protected steel ±15 °C), §3.5.7 Tab. 3.5.III (α_T), Tab. 2.5.I (ψ2 = 0), Tab. 2.6.I (γ_Q = 1.5) [R]; rigid restraint at the ends [I]"}},
      {"tie.reading.17.q", {"Sovraspessore di corrosione", "Corrosion allowance"}},
      {"tie.reading.17.r",
       {"perdita di spessore δ = 0,5 mm su ogni faccia se non data: barra e filettatura con le sezioni ridotte; la gerarchia confronta la filettatura ridotta con la barra integra",
        "a loss of thickness δ = 0.5 mm on every face unless given: rod and thread with the reduced sections; the capacity design compares the reduced thread with the intact rod"}},
      {"tie.reading.17.b",
       {"EN 1993-5 §4.4, 0,01 mm/anno in atmosfera normale per 50 anni [R]; applicata alle catene [I]",
        "EN 1993-5 §4.4, 0.01 mm/year in a normal atmosphere over 50 years [R]; applied to tie rods [I]"}},
      {"tie.reading.18.q", {"Ricerca del progetto", "Search of the design"}},
      {"tie.reading.18.r",
       {"barre dalla più piccola, classi, capochiavi (piastre, paletti) dal più piccolo, classi dei capochiavi; prima le combinazioni duttili; ogni catena esistente non verificata cambiata con il minimo intervento (capochiave, barra, rimozione); scartate senza analisi solo le combinazioni non realizzabili e quelle con lo stesso vincolo di una già analizzata",
        "rods smallest first, grades, anchors (plates, bars) smallest first, anchor grades; ductile combinations first; every existing tie that fails changed by the least change (anchor, rod, removal); only combinations that cannot be built, or with the restraint of one already analysed, are skipped without an analysis"}},
      {"tie.reading.18.b", {"note teoriche, catene §5 [I]", "docs/theory/ties.md §5 [I]"}},
      // Issue 37: changes to existing ties, the wedge drawn, a wall's ties.
      {"tie.change_title", {"Catene esistenti modificate", "Existing ties changed"}},
      {"tie.change_intro",
       {"Le catene esistenti che non sono verificate nello stato di progetto sono modificate con il minimo intervento che le rende verificate:",
        "The existing ties that fail in the design state are changed by the least change that makes them pass:"}},
      {"tie.change.anchor", {"nuovo capochiave sulla barra esistente: {}", "a new anchor on the existing rod: {}"}},
      {"tie.change.rod", {"nuova barra {} con {}, nei fori esistenti", "a new rod {} with {}, through the existing holes"}},
      {"tie.change.removed", {"rimossa", "removed"}},
      {"tie.change_short.anchor", {"nuovo capochiave", "new anchor"}},
      {"tie.change_short.rod", {"nuova barra", "new rod"}},
      {"tie.failing_existing",
       {"Catene esistenti non verificate: {}. Il caso non chiede un progetto: aggiungendo la sezione di progetto delle catene (anche senza livelli nuovi) si ottiene il minimo intervento che le rende verificate.",
        "Existing ties that fail: {}. The case asks for no design: adding the design section of the ties (even without new levels) gives the least change that makes them pass."}},
      {"tie.wedge_title", {"Il cuneo di punzonamento nella parete", "The punched wedge in the wall"}},
      {"tie.wedge_caption",
       {"Prospetto della parete attorno al capochiave della catena che governa il punzonamento ({}): il capochiave, il cuneo a 45° alla faccia interna, il coronamento, le aperture e la mezzeria dell'interasse con le catene vicine; in tratteggio il cuneo intero, a tinta piena la parte nella muratura. Area laterale nella muratura {} m² su {} m².",
        "Elevation of the wall around the anchor of the tie that governs the punching ({}): the anchor, the 45° wedge at the inner face, the crown, the openings and the middle of the spacing with the neighbouring ties; dashed the whole wedge, shaded the part in masonry. Lateral area in masonry {} m² of {} m²."}},
      {"tie.wedge_crown", {"coronamento", "crown"}},
      {"tie.wall_title", {"Catene della parete {}", "Ties of the wall {}"}},
      {"tie.wall_intro",
       {"Le catene sono date una volta sulla parete, alla loro quota, e agiscono su ogni meccanismo della parete i cui blocchi in moto attraversano: {}. Il progetto è unico per la parete e soddisfa tutti questi meccanismi insieme.",
        "The ties are given once on the wall, at their height, and act on every mechanism of the wall whose moving blocks they cross: {}. The design is one for the wall and satisfies all those mechanisms together."}},
      {"tie.wall_restrains", {"Meccanismi trattenuti", "Mechanisms restrained"}},
      {"tie.wall_governing", {"Meccanismo che governa", "Governing mechanism"}},
      {"tie.wall_member",
       {"Le catene di questa parete agiscono anche su altri suoi meccanismi ({}) e sono progettate e descritte una volta, nella sezione delle catene della parete; qui il meccanismo nei due stati.",
        "The ties of this wall act on other mechanisms of it too ({}) and are designed and described once, in the section on the wall's ties; here the mechanism in both states."}},
      {"tie.reading.caption",
       {"Catene: grandezze, valori adottati e loro base (certezza: [V-T] letto in una trascrizione del testo ufficiale, "
        "[V-S] letto in una fonte secondaria, [R] richiamato, non verificato, [I] scelta nostra; note teoriche di assess, catene).",
        "Ties: quantities, values adopted and their basis (certainty: [V-T] seen in a transcription of the official text, "
        "[V-S] seen in a secondary source, [R] recalled, not verified, [I] our choice; docs/theory/ties.md)."}},
      {"tie.reading.quantity", {"Grandezza", "Quantity"}},
      {"tie.reading.reading", {"Valore o formula adottati", "Value or formula adopted"}},
      {"tie.reading.basis", {"Base", "Basis"}},
  };
  return m;
}

}  // namespace assess::detail
