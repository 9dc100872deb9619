"""The quote document's words in English and German, and numbers, money and dates per locale.

One table (``TEXT``) holds every label of the document in both languages, so a
missing translation is a test failure rather than an English word on a German
page (``tests/api/test_quote_terms.py`` checks the table is complete). Numbers,
money and dates are formatted by Babel from the CLDR data of the locale
(``8.861,50 EUR`` and ``24.11.2026`` in German, ``8,861.50 EUR`` and
``24 Nov 2026`` in English).

Text that was entered or stored (customer, notes, terms, item descriptions, the
stored selection's check messages) is shown as it was written.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import date
from decimal import Decimal
from typing import Any, Literal

from babel.dates import format_date
from babel.numbers import format_currency, format_decimal
from markupsafe import Markup

from actuator_selection.core.money import ROUNDING_RULE
from actuator_selection.core.quote_terms import LANGUAGES, VAT_ROUNDING_RULE
from actuator_selection.core.symbols import MINUS, symbols

Language = Literal["en", "de"]

LOCALES: dict[str, str] = {"en": "en_GB", "de": "de_DE"}
"""The Babel locale of each document language (en_GB: day before month, unambiguous
for customers outside the US too)."""

TEXT: dict[str, dict[str, str]] = {
    "title": {"en": "Quote {number}", "de": "Angebot {number}"},
    "print_hint": {
        "en": "Print this page (Ctrl+P) to A4 or to PDF; the layout is made for it.",
        "de": "Diese Seite (Strg+P) auf A4 oder als PDF drucken; das Layout ist dafür gemacht.",
    },
    "page": {"en": "Page", "de": "Seite"},
    "of": {"en": "of", "de": "von"},
    "example_banner": {
        "en": "EXAMPLE PRICES — not real prices. The price list “{name}” holds invented "
        "figures for trying the service out; do not send this document to a customer.",
        "de": "BEISPIELPREISE — keine echten Preise. Die Preisliste „{name}“ enthält "
        "erfundene Zahlen zum Ausprobieren; dieses Dokument nicht an Kunden senden.",
    },
    "placeholder_seller": {
        "en": "The seller block holds placeholder values: set the seller's name, address, "
        "VAT ID and email in the server's settings (docs/deployment.md) before sending quotes.",
        "de": "Der Anbieterblock enthält Platzhalter: vor dem Versand Name, Anschrift, "
        "USt-IdNr. und E-Mail des Anbieters in den Servereinstellungen setzen "
        "(docs/deployment.md).",
    },
    "heading": {"en": "Quotation", "de": "Angebot"},
    "subtitle": {
        "en": "Harmonic Drive servo actuator, sized by the actuator selection service",
        "de": "Harmonic-Drive-Servoantrieb, ausgelegt mit dem Antriebsauswahl-Service",
    },
    "quote_details": {"en": "quote details", "de": "Angebotsdaten"},
    "number": {"en": "Quote no.", "de": "Angebotsnr."},
    "date": {"en": "Date", "de": "Datum"},
    "valid_until": {"en": "Valid until", "de": "Gültig bis"},
    "status": {"en": "Status", "de": "Status"},
    "status_draft": {"en": "draft", "de": "Entwurf"},
    "status_sent": {"en": "sent", "de": "versendet"},
    "status_accepted": {"en": "accepted", "de": "angenommen"},
    "status_rejected": {"en": "rejected", "de": "abgelehnt"},
    "status_expired": {"en": "expired", "de": "abgelaufen"},
    "seller": {"en": "Seller", "de": "Anbieter"},
    "vat_id": {"en": "VAT ID", "de": "USt-IdNr."},
    "email": {"en": "Email", "de": "E-Mail"},
    "phone": {"en": "Phone", "de": "Telefon"},
    "customer": {"en": "Customer", "de": "Kunde"},
    "your_reference": {"en": "Your reference", "de": "Ihre Referenz"},
    "unconfirmed_banner": {
        "en": "Suitability unconfirmed: no check failed, but these could not be made for "
        "lack of published data:",
        "de": "Eignung nicht bestätigt: keine Prüfung ist fehlgeschlagen, aber diese waren "
        "mangels veröffentlichter Daten nicht möglich:",
    },
    "items": {"en": "Items", "de": "Positionen"},
    "col_position": {"en": "Pos.", "de": "Pos."},
    "col_item": {"en": "Item", "de": "Artikel"},
    "col_description": {"en": "Description", "de": "Beschreibung"},
    "col_quantity": {"en": "Qty", "de": "Menge"},
    "col_unit_price": {"en": "Unit price", "de": "Einzelpreis"},
    "col_amount": {"en": "Amount", "de": "Betrag"},
    "subtotal": {"en": "Subtotal", "de": "Zwischensumme"},
    "discount": {"en": "Discount {percent} %", "de": "Rabatt {percent} %"},
    "net_total": {"en": "Net total", "de": "Nettobetrag"},
    "vat": {"en": "VAT {percent} %", "de": "zzgl. {percent} % USt."},
    "gross_total": {"en": "Total ({currency}, including VAT)", "de": "Gesamtbetrag ({currency})"},
    "total_no_tax": {
        "en": "Total ({currency}, excluding taxes)",
        "de": "Gesamt ({currency}, ohne Steuern)",
    },
    "prices_from": {
        "en": "Prices from the price list “{name}”, valid on {date}.",
        "de": "Preise aus der Preisliste „{name}“, gültig am {date}.",
    },
    "rounding": {
        "en": f"Rounding: {ROUNDING_RULE}.",
        "de": "Rundung: jeder Positionsbetrag (Einzelpreis × Menge) wird kaufmännisch auf "
        "Cent gerundet; die Zwischensumme ist ihre Summe; der Rabatt (Zwischensumme × "
        "Prozentsatz / 100) wird kaufmännisch auf Cent gerundet; Nettobetrag = "
        "Zwischensumme − Rabatt.",
    },
    "vat_rounding": {
        "en": f"{VAT_ROUNDING_RULE}.",
        "de": "USt. = Nettobetrag × Steuersatz / 100, einmal kaufmännisch auf Cent gerundet; "
        "Gesamtbetrag = Nettobetrag + USt.",
    },
    "terms": {"en": "Terms", "de": "Konditionen"},
    "payment_terms": {"en": "Payment terms", "de": "Zahlungsbedingungen"},
    "delivery_terms": {"en": "Delivery terms", "de": "Lieferbedingungen"},
    "validity": {"en": "Validity", "de": "Bindefrist"},
    "validity_text": {
        "en": "This offer is valid until {date} (inclusive).",
        "de": "Dieses Angebot ist gültig bis einschließlich {date}.",
    },
    "notes": {"en": "Notes", "de": "Anmerkungen"},
    "justification": {"en": "Engineering justification", "de": "Technische Begründung"},
    "justification_intro": {
        "en": "{model} for the load case below, by <em translate='no'>Engineering Data for "
        "Harmonic Drive Servo Actuators</em>. Verdict: "
        "<strong data-field='verdict'>{verdict}</strong>.",
        "de": "{model} für den unten stehenden Lastfall, nach <em lang='en' translate='no'>"
        "Engineering Data for Harmonic Drive Servo Actuators</em>. Ergebnis: "
        "<strong data-field='verdict'>{verdict}</strong>.",
    },
    "verdict_suitable": {"en": "suitable", "de": "geeignet"},
    "verdict_unconfirmed": {"en": "unconfirmed", "de": "nicht bestätigt"},
    "verdict_unsuitable": {"en": "unsuitable", "de": "ungeeignet"},
    # The engineering report of a selection (services/report_pdf.py)
    "report_title": {"en": "Selection report", "de": "Auswahlbericht"},
    "report_document_title": {"en": "Selection report {id}", "de": "Auswahlbericht {id}"},
    "report_intro": {
        "en": "Selection {id} of {date}, {time} UTC, catalogue version {version}. Sized by "
        "Engineering Data for Harmonic Drive Servo Actuators (Eq. 514.1–522.3); every figure "
        "is the one stored with the selection.",
        "de": "Auswahl {id} vom {date}, {time} UTC, Katalogversion {version}. Ausgelegt nach "
        "Engineering Data for Harmonic Drive Servo Actuators (Gl. 514.1–522.3); jede Zahl ist "
        "die mit der Auswahl gespeicherte.",
    },
    "inputs_heading": {"en": "Inputs", "de": "Eingaben"},
    "diagrams_heading": {
        "en": "Cycle and speed/torque diagram of the first-ranked candidate",
        "de": "Zyklus und Drehzahl-Drehmoment-Diagramm des erstplatzierten Kandidaten",
    },
    "report_chosen": {"en": "First-ranked candidate", "de": "Erstplatzierter Kandidat"},
    "report_top": {
        "en": "The first {top} of {count} candidates, ranked as answered",
        "de": "Die ersten {top} von {count} Kandidaten, in der Rangfolge der Antwort",
    },
    "report_details_hint": {
        "en": "Utilisation = value/limit. The checks of further candidates are listed when "
        "the report is asked for with ?candidates=MODEL; every candidate's checks are in "
        "the CSV.",
        "de": "Auslastung = Wert/Grenzwert. Die Prüfungen weiterer Kandidaten enthält der "
        "Bericht mit ?candidates=MODELL; die Prüfungen aller Kandidaten enthält die CSV-Datei.",
    },
    "col_model": {"en": "Model", "de": "Modell"},
    "col_verdict": {"en": "Verdict", "de": "Ergebnis"},
    "col_utilisation": {"en": "Utilisation", "de": "Auslastung"},
    "utilisation_peak_torque": {"en": "T_1/T_max", "de": "T_1/T_max"},
    "utilisation_continuous_duty": {"en": "T_rms/continuous", "de": "T_rms/Dauergrenze"},
    "utilisation_max_speed": {"en": "n_2/n_max", "de": "n_2/n_max"},
    "cycle_speed": {"en": "output speed n", "de": "Abtriebsdrehzahl n"},
    "axis_time": {"en": "time t [s]", "de": "Zeit t [s]"},
    "load_heading": {"en": "Load (at the actuator output)", "de": "Last (am Abtrieb)"},
    "torques_heading": {"en": "Torques (Eq. 514.1, 514.2)", "de": "Drehmomente (Gl. 514.1, 514.2)"},
    "cycle_heading": {"en": "Cycle (Fig. 516.2)", "de": "Zyklus (Abb. 516.2)"},
    "catalogue_heading": {"en": "Catalogue data used", "de": "Verwendete Katalogdaten"},
    "checks_heading": {
        "en": "Checks of the selection flowchart",
        "de": "Prüfungen des Auswahlablaufs",
    },
    "col_check": {"en": "Check", "de": "Prüfung"},
    "col_result": {"en": "Result", "de": "Ergebnis"},
    "col_value": {"en": "Value", "de": "Wert"},
    "col_limit": {"en": "Limit", "de": "Grenzwert"},
    "col_margin": {"en": "Margin", "de": "Reserve"},
    "col_reference": {"en": "Reference", "de": "Quelle"},
    "diagram_heading": {"en": "Speed/torque diagram", "de": "Drehzahl-Drehmoment-Diagramm"},
    "diagram_label": {
        "en": "speed/torque diagram of {model} with the operating points",
        "de": "Drehzahl-Drehmoment-Diagramm von {model} mit den Betriebspunkten",
    },
    "load_speed": {"en": "Load speed n₂", "de": "Lastdrehzahl n₂"},
    "load_torque": {"en": "Load torque T_L", "de": "Lastmoment T_L"},
    "load_inertia": {"en": "Load inertia J_L", "de": "Lastträgheitsmoment J_L"},
    "high_dynamics": {
        "en": "J_L ≤ 3·J_A binding (high dynamics)",
        "de": "J_L ≤ 3·J_A verbindlich (hohe Dynamik)",
    },
    "yes": {"en": "yes", "de": "ja"},
    "no": {"en": "no", "de": "nein"},
    "mechanism": {"en": "Mechanism (as entered)", "de": "Mechanik (wie eingegeben)"},
    # The load as entered (the stored request's ``load``), field by field
    "load_ball_screw": {"en": "ball screw", "de": "Kugelgewindetrieb"},
    "load_rotary_table": {"en": "rotary table", "de": "Drehtisch"},
    "load_ball_screw_incline": {
        "en": "ball screw, inclined or vertical",
        "de": "Kugelgewindetrieb, geneigt oder senkrecht",
    },
    "load_belt": {"en": "toothed belt", "de": "Zahnriemen"},
    "load_rack_pinion": {"en": "rack and pinion", "de": "Zahnstange und Ritzel"},
    "load_conveyor": {"en": "conveyor", "de": "Förderband"},
    "load_lift": {"en": "lift (rope drum)", "de": "Hubwerk (Seiltrommel)"},
    "load_rotary": {"en": "rotary load", "de": "Drehbewegung"},
    "field_speed_rpm": {"en": "Load speed n_2", "de": "Lastdrehzahl n_2"},
    "field_speed": {"en": "Load speed v", "de": "Lastgeschwindigkeit v"},
    "field_torque_nm": {"en": "Load torque T_L", "de": "Lastmoment T_L"},
    "field_inertia_kgm2": {"en": "Load inertia J_L", "de": "Lastträgheitsmoment J_L"},
    "field_gravity_torque_nm": {"en": "Gravity torque T_g", "de": "Gewichtsmoment T_g"},
    "field_efficiency": {"en": "Efficiency η", "de": "Wirkungsgrad η"},
    "field_mass_kg": {"en": "Moved mass m", "de": "Bewegte Masse m"},
    "field_load_mass_kg": {"en": "Load mass m_L", "de": "Lastmasse m_L"},
    "field_lead_m": {"en": "Screw lead P", "de": "Spindelsteigung P"},
    "field_lead_mm": {"en": "Screw lead P", "de": "Spindelsteigung P"},
    "field_friction_coefficient": {
        "en": "Coefficient of friction μ",
        "de": "Reibungskoeffizient μ",
    },
    "field_screw_inertia_kgm2": {
        "en": "Screw inertia J_S",
        "de": "Trägheitsmoment der Spindel J_S",
    },
    "field_diameter_m": {"en": "Table diameter D", "de": "Durchmesser des Tisches D"},
    "field_friction_radius_m": {"en": "Friction radius r_f", "de": "Radius der Reibung r_f"},
    "field_incline_deg": {"en": "Incline α", "de": "Neigung α"},
    "field_counterweight_kg": {"en": "Counterweight m_c", "de": "Gegengewicht m_c"},
    "field_friction_force_n": {"en": "Friction force F_f", "de": "Reibkraft F_f"},
    "field_friction_torque_nm": {"en": "Friction torque T_f", "de": "Reibmoment T_f"},
    "field_pulley_diameter_mm": {
        "en": "Drive pulley pitch diameter D",
        "de": "Wirkdurchmesser der Antriebsscheibe D",
    },
    "field_belt_mass_kg": {"en": "Belt mass m_B", "de": "Masse des Riemens m_B"},
    "field_pulley_inertia_kgm2": {
        "en": "Drive pulley inertia",
        "de": "Trägheitsmoment der Antriebsscheibe",
    },
    "field_idler_inertia_kgm2": {"en": "Idler inertia", "de": "Trägheitsmoment der Umlenkscheibe"},
    "field_idler_diameter_mm": {"en": "Idler diameter", "de": "Durchmesser der Umlenkscheibe"},
    "field_pinion_diameter_mm": {
        "en": "Pinion pitch diameter d",
        "de": "Teilkreisdurchmesser des Ritzels d",
    },
    "field_pinion_inertia_kgm2": {"en": "Pinion inertia", "de": "Trägheitsmoment des Ritzels"},
    "field_roller_diameter_mm": {
        "en": "Drive roller diameter D",
        "de": "Durchmesser der Antriebsrolle D",
    },
    "field_drive_roller_inertia_kgm2": {
        "en": "Drive roller inertia",
        "de": "Trägheitsmoment der Antriebsrolle",
    },
    "field_tail_roller_inertia_kgm2": {
        "en": "Tail roller inertia",
        "de": "Trägheitsmoment der Umlenkrolle",
    },
    "field_tail_roller_diameter_mm": {
        "en": "Tail roller diameter",
        "de": "Durchmesser der Umlenkrolle",
    },
    "field_drum_diameter_mm": {"en": "Drum diameter D", "de": "Trommeldurchmesser D"},
    "field_drum_inertia_kgm2": {"en": "Drum inertia", "de": "Trägheitsmoment der Trommel"},
    "field_transmission_ratio": {"en": "Transmission ratio i", "de": "Übersetzung i"},
    "field_transmission_inertia_kgm2": {
        "en": "Transmission inertia J_tr",
        "de": "Trägheitsmoment der Übersetzung J_tr",
    },
    "field_transmission_efficiency": {
        "en": "Transmission efficiency η_tr",
        "de": "Wirkungsgrad der Übersetzung η_tr",
    },
    "accel_time": {"en": "Acceleration t₁", "de": "Beschleunigung t₁"},
    "constant_time": {"en": "Constant speed t₂", "de": "Konstantfahrt t₂"},
    "decel_time": {"en": "Deceleration t₃", "de": "Verzögerung t₃"},
    "pause_time": {"en": "Pause t_p", "de": "Pause t_p"},
    "segment_duration_s": {"en": "Segment {k}: duration", "de": "Abschnitt {k}: Dauer"},
    "segment_start_rpm": {"en": "Segment {k}: start speed", "de": "Abschnitt {k}: Anfangsdrehzahl"},
    "segment_end_rpm": {"en": "Segment {k}: end speed", "de": "Abschnitt {k}: Enddrehzahl"},
    "cycle_time": {"en": "Cycle time t₀", "de": "Zykluszeit t₀"},
    "mean_speed": {"en": "Mean speed n_av (Eq. 514.3)", "de": "Mittlere Drehzahl n_av (Gl. 514.3)"},
    "duty_cycle": {"en": "Duty cycle ED (Eq. 514.4)", "de": "Einschaltdauer ED (Gl. 514.4)"},
    "accel_torque": {"en": "Acceleration T₁", "de": "Beschleunigung T₁"},
    "constant_torque": {"en": "Constant speed T₂", "de": "Konstantfahrt T₂"},
    "decel_torque": {"en": "Deceleration T₃", "de": "Verzögerung T₃"},
    "rms_torque": {"en": "RMS T_rms", "de": "Effektivwert T_rms"},
    "family_ratio": {"en": "Family, gear ratio", "de": "Baureihe, Untersetzung"},
    "max_torque": {"en": "Peak torque T_max", "de": "Maximales Drehmoment T_max"},
    "max_speed": {"en": "Max. speed n_max", "de": "Maximale Drehzahl n_max"},
    "inertia": {"en": "Inertia J_A", "de": "Trägheitsmoment J_A"},
    "stall_torque": {"en": "Stall torque T₀", "de": "Stillstandsdrehmoment T₀"},
    "check_max_speed": {"en": "Maximum speed n₂ ≤ n_max", "de": "Maximaldrehzahl n₂ ≤ n_max"},
    "check_inertia_ratio": {
        "en": "Inertia ratio J_L ≤ 3·J_A",
        "de": "Trägheitsverhältnis J_L ≤ 3·J_A",
    },
    "check_peak_torque": {
        "en": "Acceleration torque T₁ ≤ T_max",
        "de": "Beschleunigungsmoment T₁ ≤ T_max",
    },
    "check_decel_torque": {
        "en": "Deceleration torque |T₃| ≤ T_max",
        "de": "Verzögerungsmoment |T₃| ≤ T_max",
    },
    "check_continuous_duty": {
        "en": "Continuous duty (n_av, T_rms) in zone",
        "de": "Dauerbetrieb (n_av, T_rms) im Bereich",
    },
    "check_thermal_peak": {
        "en": "Winding heating over the cycle ≤ continuous limit",
        "de": "Wicklungserwärmung über den Zyklus ≤ Dauergrenze",
    },
    "check_continuous_speed": {
        "en": "Continuous speed n_th (heating) ≤ continuous or rated speed",
        "de": "Dauerdrehzahl n_th (Erwärmung) ≤ Dauer- bzw. Nenndrehzahl",
    },
    "check_brake_holding": {
        "en": "Holding brake: T_L at standstill ≤ holding torque",
        "de": "Haltebremse: T_L im Stillstand ≤ Haltemoment",
    },
    "check_drive_current": {
        "en": "Peak motor current ≤ I_max",
        "de": "Maximaler Motorstrom ≤ I_max",
    },
    "check_drive_voltage": {
        "en": "Output voltage with ωL·I ≤ DC bus output",
        "de": "Ausgangsspannung mit ωL·I ≤ Zwischenkreis-Ausgang",
    },
    "check_bearing_moment": {
        "en": "Output bearing: tilting moment ≤ allowable",
        "de": "Abtriebslager: Kippmoment ≤ zulässig",
    },
    "check_bearing_static_safety": {
        "en": "Output bearing: static safety f_s ≥ required",
        "de": "Abtriebslager: statische Sicherheit f_s ≥ gefordert",
    },
    "check_bearing_life": {
        "en": "Output bearing: L₁₀ life ≥ required",
        "de": "Abtriebslager: Lebensdauer L₁₀ ≥ gefordert",
    },
    "check_bearing_fretting": {
        "en": "Output bearing: swing ≥ 5° (fretting)",
        "de": "Abtriebslager: Schwenkwinkel ≥ 5° (Passungsrost)",
    },
    "result_pass": {"en": "pass", "de": "bestanden"},
    "result_fail": {"en": "FAIL", "de": "NICHT BESTANDEN"},
    "result_warn": {"en": "warning", "de": "Warnung"},
    "result_no_data": {"en": "no data", "de": "keine Daten"},
    "approximate": {"en": " (approx.)", "de": " (näherungsweise)"},
    "times_limit": {"en": "{factor} × limit", "de": "{factor} × Grenzwert"},
    "zone": {"en": "continuous-duty zone", "de": "Dauerbetriebsbereich"},
    "zone_approximate": {
        "en": "continuous limit (approximate)",
        "de": "Dauergrenze (näherungsweise)",
    },
    "point_accel": {"en": "T₁ (acceleration)", "de": "T₁ (Beschleunigung)"},
    "point_decel": {"en": "|T₃| (deceleration)", "de": "|T₃| (Verzögerung)"},
    "point_rms": {"en": "T_rms at n_av", "de": "T_rms bei n_av"},
    "axis_speed": {"en": "output speed n [{rpm}]", "de": "Abtriebsdrehzahl n [{rpm}]"},
    "axis_torque": {"en": "output torque T [Nm]", "de": "Abtriebsdrehmoment T [Nm]"},
    "rpm": {"en": "rpm", "de": "min⁻¹"},
    # The chapter's reference words, as a check's stored reference uses them.
    "ref_Table": {"en": "Table", "de": "Tabelle"},
    "ref_Eq.": {"en": "Eq.", "de": "Gl."},
    "ref_Fig.": {"en": "Fig.", "de": "Abb."},
    "ref_model": {"en": "model", "de": "Modell"},
    "ref_with ωL·I in quadrature": {
        "en": "with ωL·I in quadrature",
        "de": "mit ωL·I in Quadratur",
    },
    "catalogue_source": {"en": "Catalogue data: {source}.", "de": "Katalogdaten: {source}."},
    "selection_footer": {
        "en": "Selection {id} of {date}, made with catalogue version {version}; catalogue "
        "version {quote_version} when this quote was made.",
        "de": "Auswahl {id} vom {date}, erstellt mit Katalogversion {version}; "
        "Katalogversion {quote_version} bei Erstellung dieses Angebots.",
    },
    "version_note": {
        "en": " The catalogue changed between selection and quote (v{old} → v{new}); the "
        "justification shows the selection's figures.",
        "de": " Der Katalog hat sich zwischen Auswahl und Angebot geändert (v{old} → v{new}); "
        "die Begründung zeigt die Zahlen der Auswahl.",
    },
    # The service's own item descriptions (services/quotes.py), worded again for the reader
    "item_actuator": {
        "en": "Servo actuator {model} ({family}, gear ratio {ratio})",
        "de": "Servoantrieb {model} ({family}, Untersetzung {ratio})",
    },
    "item_controller": {"en": "Servo controller {type_name}", "de": "Servoregler {type_name}"},
    "item_controller_row": {
        "en": "Servo controller {type_name} ({controller}, Table 521.1 row {row}: {level})",
        "de": "Servoregler {type_name} ({controller}, Tabelle 521.1 Zeile {row}: {level})",
    },
    "level_tested": {"en": "tested", "de": "praktisch erprobt"},
    "level_possible": {"en": "possible", "de": "theoretisch machbar"},
    "level_unconfirmed": {"en": "unconfirmed", "de": "nicht bestätigt"},
    "figures_fixed": {
        "en": "Figures are those computed by the service and stored with the selection; "
        "they do not change afterwards.",
        "de": "Die Zahlen sind die vom Service berechneten und mit der Auswahl gespeicherten; "
        "sie ändern sich danach nicht.",
    },
}


_SEGMENT_FACT = re.compile(r"segment_(\d+)_(duration_s|start_rpm|end_rpm)")
_CYCLE_FACTS = {
    "accel_s": "accel_time",
    "constant_s": "constant_time",
    "decel_s": "decel_time",
    "pause_s": "pause_time",
}

_REFERENCE_WORD = re.compile(r"\bTable\b|\bEq\.|\bFig\.|(?<=\()model(?=\))|with ωL·I in quadrature")


def negotiate_language(query: str | None, accept_language: str | None) -> Language:
    """The document's language: ``query`` (``?lang=``) if given, else the first language of
    ``Accept-Language`` (by quality) that the document is written in, else English.

    >>> negotiate_language(None, "fr-CH, fr;q=0.9, de;q=0.8, en;q=0.7")
    'de'
    >>> negotiate_language("en", "de-DE")
    'en'
    >>> negotiate_language(None, "de;q=0, en-US")
    'en'
    >>> negotiate_language(None, None)
    'en'
    """
    if query in LANGUAGES:
        return "de" if query == "de" else "en"
    ranked: list[tuple[float, int, str]] = []
    for index, part in enumerate((accept_language or "").split(",")):
        tag, _, params = part.strip().partition(";")
        quality = 1.0
        for param in params.split(";"):
            name, _, value = param.strip().partition("=")
            if name.strip().lower() == "q":
                try:
                    quality = float(value)
                except ValueError:
                    quality = 0.0
        primary = tag.strip().lower().split("-")[0]
        if primary in LANGUAGES and quality > 0:
            ranked.append((-quality, index, primary))
    if not ranked:
        return "en"
    return "de" if min(ranked)[2] == "de" else "en"


@dataclass(frozen=True, slots=True)
class DocumentText:
    """The document's words and formats in one language."""

    language: Language

    @property
    def locale(self) -> str:
        """The Babel locale."""
        return LOCALES[self.language]

    def __call__(self, key: str, **params: object) -> str:
        """The label ``key`` in this language, with ``params`` filled in (not escaped)."""
        text = TEXT[key][self.language]
        return text.format(**params) if params else text

    def number(self, value: float, pattern: str) -> str:
        """``value`` by a CLDR number ``pattern`` (``#,##0.00``) with this locale's symbols."""
        return format_decimal(value, format=pattern, locale=self.locale).replace("-", MINUS)

    def words(self, key: str, **params: object) -> Markup:
        """The label ``key`` as a document shows it: symbols subscripted (:func:`symbols`)."""
        return symbols(self(key, **params))

    def message(self, text: str) -> Markup:
        """A check's message (already in this language) as a document shows it."""
        return symbols(text)

    def load_rows(self, load: Mapping[str, Any]) -> list[tuple[Markup, str]]:
        """The load as entered, in this language (:func:`load_rows`)."""
        return load_rows(self, load)

    def money(self, amount: Decimal, currency: str) -> str:
        """``8,861.50 EUR`` / ``8.861,50 EUR``: always two decimals (whole cents), the ISO
        code after the amount."""
        return format_currency(
            amount, currency, format="#,##0.00 ¤¤", locale=self.locale, currency_digits=False
        ).replace("-", MINUS)

    def percent(self, value: Decimal) -> str:
        """A rate as written on the document: ``7.5`` / ``7,5``, ``19``."""
        return format_decimal(value, format="#,##0.##", locale=self.locale)

    def date(self, value: date) -> str:
        """``24 Nov 2026`` / ``24.11.2026``."""
        return format_date(value, format="medium", locale=self.locale)

    def reference(self, reference: str) -> str:
        """A stored reference (``Table 515.1; Eq. 514.1``) with the chapter's words in this
        language (``Tabelle 515.1; Gl. 514.1``).

        >>> DocumentText("de").reference("Table 515.1, Eq. 514.2 and Fig. 517.1")
        'Tabelle 515.1, Gl. 514.2 and Abb. 517.1'
        >>> DocumentText("de").reference("Fig. 520.1 (model); Eq. 514.2")
        'Abb. 520.1 (Modell); Gl. 514.2'
        >>> DocumentText("de").reference("Eq. 521.2 with ωL·I in quadrature (560vdc bus)")
        'Gl. 521.2 mit ωL·I in Quadratur (560vdc bus)'
        """
        return _REFERENCE_WORD.sub(lambda m: self(f"ref_{m.group(0)}"), reference)

    def cycle_label(self, key: str, label: str) -> str:
        """The label of a cycle fact (``schemas.quotes.cycle_facts``: its key and English
        label) in this language.

        >>> DocumentText("de").cycle_label("segment_2_end_rpm", "segment 2: end speed")
        'Abschnitt 2: Enddrehzahl'
        """
        if key in _CYCLE_FACTS:
            return self(_CYCLE_FACTS[key])
        if (match := _SEGMENT_FACT.fullmatch(key)) is not None:
            return self(f"segment_{match.group(2)}", k=match.group(1))
        return label[:1].upper() + label[1:]

    def unit(self, unit: str) -> str:
        """A unit as the chapter prints it in this language (min⁻¹ for rpm in German)."""
        return self("rpm") if unit == "rpm" else unit


_FIELD_UNITS = (
    ("_kgm2", "kgm²"),
    ("_kg", "kg"),
    ("_mm", "mm"),
    ("_m", "m"),
    ("_nm", "Nm"),
    ("_n", "N"),
    ("_deg", "°"),
    ("_rpm", "rpm"),
)
"""A load field's unit by the suffix of its name (``schemas/selections.py``,
``schemas/mechanisms.py``: SI or mm, as the request sends them)."""


def field_unit(name: str, load_type: str | None) -> str:
    """The unit of the load field ``name`` (``speed`` is mm/s on a linear axis, rpm on a
    rotary load).

    >>> field_unit("pulley_diameter_mm", "belt"), field_unit("speed", "belt")
    ('mm', 'mm/s')
    """
    if name == "speed":
        return "rpm" if load_type == "rotary" else "mm/s"
    return next((unit for suffix, unit in _FIELD_UNITS if name.endswith(suffix)), "")


def load_rows(t: DocumentText, load: Mapping[str, Any]) -> list[tuple[Markup, str]]:
    """The load as it was entered (a stored request's ``load``), one (label, value) row a
    field, in ``t``'s words: the load type named, each field by its name and symbol, each
    number with its unit as the chapter prints it; a value sent as text with its own unit
    (``"0.5 in"``) as it was sent.

    >>> rows = load_rows(DocumentText("de"), {"type": "rotary_table", "speed_rpm": 45.0,
    ...     "mass_kg": 30.0, "friction_coefficient": -0.5})
    >>> for label, value in rows:
    ...     print(f"{label}: {value}")
    Mechanik (wie eingegeben): Drehtisch
    Lastdrehzahl n<sub>2</sub>: 45 min⁻¹
    Bewegte Masse m: 30 kg
    Reibungskoeffizient μ: −0,5
    """
    kind = load.get("type")
    rows: list[tuple[Markup, str]] = []
    if isinstance(kind, str):
        rows.append((t.words("mechanism"), _label_or(t, f"load_{kind}", kind)))
    for name, value in load.items():
        if name == "type" or value is None:
            continue
        if isinstance(value, dict):
            rows += [
                (t.words(f"field_{name}_{sub}") if f"field_{name}_{sub}" in TEXT
                 else symbols(f"{name} {sub}".replace("_", " ")),
                 _field_value(t, v, field_unit(sub, kind)))
                for sub, v in value.items()
                if v is not None
            ]  # fmt: skip
            continue
        label = (
            t.words(f"field_{name}") if f"field_{name}" in TEXT else symbols(name.replace("_", " "))
        )
        rows.append((label, _field_value(t, value, field_unit(name, kind))))
    return rows


def _label_or(t: DocumentText, key: str, fallback: str) -> str:
    return t(key) if key in TEXT else fallback.replace("_", " ")


def _field_value(t: DocumentText, value: object, unit: str) -> str:
    if isinstance(value, bool):
        return t("yes" if value else "no")
    if isinstance(value, int | float):
        return f"{t.number(value, '#,##0.######')} {t.unit(unit)}".strip()
    return str(value)
