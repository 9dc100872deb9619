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
from dataclasses import dataclass
from datetime import date
from decimal import Decimal
from typing import Literal

from babel.dates import format_date
from babel.numbers import format_currency, format_decimal

from actuator_selection.core.money import ROUNDING_RULE
from actuator_selection.core.quote_terms import LANGUAGES, VAT_ROUNDING_RULE

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
        "en": "The seller block holds placeholder values: set SELLER_NAME, SELLER_ADDRESS, "
        "SELLER_VAT_ID and SELLER_EMAIL in the server's settings before sending quotes.",
        "de": "Der Anbieterblock enthält Platzhalter: vor dem Versand SELLER_NAME, "
        "SELLER_ADDRESS, SELLER_VAT_ID und SELLER_EMAIL in den Servereinstellungen setzen.",
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
    "report_candidates": {
        "en": "Candidates ({count}, ranked as answered)",
        "de": "Kandidaten ({count}, in der Rangfolge der Antwort)",
    },
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
    "result_pass": {"en": "pass", "de": "bestanden"},
    "result_fail": {"en": "FAIL", "de": "NICHT BESTANDEN"},
    "result_warn": {"en": "warning", "de": "Warnung"},
    "result_no_data": {"en": "no data", "de": "keine Daten"},
    "approximate": {"en": " (approx.)", "de": " (näherungsweise)"},
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
    # The PDF of the document (services/quote_pdf.py)
    "pdf_diagram_note": {
        "en": "The speed/torque diagram is in the HTML document.",
        "de": "Das Drehzahl-Drehmoment-Diagramm enthält das HTML-Dokument.",
    },
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

_REFERENCE_WORD = re.compile(r"\bTable\b|\bEq\.|\bFig\.|(?<=\()model(?=\))")


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
        return format_decimal(value, format=pattern, locale=self.locale)

    def money(self, amount: Decimal, currency: str) -> str:
        """``8,861.50 EUR`` / ``8.861,50 EUR``: always two decimals (whole cents), the ISO
        code after the amount."""
        return format_currency(
            amount, currency, format="#,##0.00 ¤¤", locale=self.locale, currency_digits=False
        )

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
