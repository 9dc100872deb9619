// GENERATED from the request models by `make mechanisms`
// (backend/actuator_selection/schemas/mechanism_spec.py; the same answer as
// GET /api/v1/mechanisms). Do not edit: tests/api/test_mechanism_spec.py fails when stale.

/**
 * @typedef {object} FieldSpec
 * @property {string} name
 * @property {string} symbol
 * @property {string} label
 * @property {string} unit
 * @property {boolean} units
 * @property {boolean} required
 * @property {number | null} default
 * @property {number | null} minimum
 * @property {number | null} maximum
 * @property {boolean} exclusive_minimum
 *
 * @typedef {object} MechanismSpec
 * @property {string} type
 * @property {string} label
 * @property {string | null} hint
 * @property {string | null} equation
 * @property {"speed_rpm" | "speed"} speed_field
 * @property {boolean} linear
 * @property {boolean} transmission
 * @property {FieldSpec[]} fields
 *
 * @typedef {object} MechanismsSpec
 * @property {MechanismSpec[]} kinds
 * @property {FieldSpec[]} transmission
 */

/** @type {MechanismsSpec} */
export const SPEC = {
  "kinds": [
    {
      "type": "direct",
      "label": "load.direct",
      "hint": null,
      "equation": null,
      "speed_field": "speed_rpm",
      "linear": false,
      "transmission": false,
      "fields": [
        {
          "name": "torque_nm",
          "symbol": "T_L",
          "label": "load.torque",
          "unit": "Nm",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "inertia_kgm2",
          "symbol": "J_L",
          "label": "load.inertia",
          "unit": "kgm²",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "gravity_torque_nm",
          "symbol": "T_G",
          "label": "load.gravity",
          "unit": "Nm",
          "units": false,
          "required": false,
          "default": 0.0,
          "minimum": -1000000.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": false,
          "default": 1.0,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "ball_screw",
      "label": "load.ball_screw",
      "hint": null,
      "equation": "load.ball_screw.eq",
      "speed_field": "speed_rpm",
      "linear": false,
      "transmission": false,
      "fields": [
        {
          "name": "mass_kg",
          "symbol": "m",
          "label": "load.mass",
          "unit": "kg",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "lead_m",
          "symbol": "P",
          "label": "load.lead",
          "unit": "m",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 1e-06,
          "maximum": 100.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "screw_inertia_kgm2",
          "symbol": "J_S",
          "label": "load.screw_inertia",
          "unit": "kgm²",
          "units": false,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "rotary_table",
      "label": "load.rotary_table",
      "hint": null,
      "equation": "load.rotary_table.eq",
      "speed_field": "speed_rpm",
      "linear": false,
      "transmission": false,
      "fields": [
        {
          "name": "mass_kg",
          "symbol": "m",
          "label": "load.mass",
          "unit": "kg",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "diameter_m",
          "symbol": "D",
          "label": "load.diameter",
          "unit": "m",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 1e-06,
          "maximum": 100.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_radius_m",
          "symbol": "r",
          "label": "load.friction_radius",
          "unit": "m",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 100.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "ball_screw_incline",
      "label": "load.ball_screw_incline",
      "hint": "mech.ball_screw_incline.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": true,
      "transmission": true,
      "fields": [
        {
          "name": "mass_kg",
          "symbol": "m",
          "label": "mech.mass",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "lead_mm",
          "symbol": "P",
          "label": "load.lead",
          "unit": "mm",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "incline_deg",
          "symbol": "θ",
          "label": "mech.incline",
          "unit": "°",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": -90.0,
          "maximum": 90.0,
          "exclusive_minimum": false
        },
        {
          "name": "screw_inertia_kgm2",
          "symbol": "J_S",
          "label": "load.screw_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "counterweight_kg",
          "symbol": "m_c",
          "label": "mech.counterweight",
          "unit": "kg",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_force_n",
          "symbol": "F_R",
          "label": "mech.friction_force",
          "unit": "N",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 10000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "belt",
      "label": "load.belt",
      "hint": "mech.belt.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": true,
      "transmission": true,
      "fields": [
        {
          "name": "mass_kg",
          "symbol": "m",
          "label": "mech.mass",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "pulley_diameter_mm",
          "symbol": "D",
          "label": "mech.pulley_diameter",
          "unit": "mm",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "incline_deg",
          "symbol": "θ",
          "label": "mech.incline",
          "unit": "°",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": -90.0,
          "maximum": 90.0,
          "exclusive_minimum": false
        },
        {
          "name": "belt_mass_kg",
          "symbol": "m_B",
          "label": "mech.belt_mass",
          "unit": "kg",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "pulley_inertia_kgm2",
          "symbol": "J_D",
          "label": "mech.pulley_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "idler_inertia_kgm2",
          "symbol": "J_I",
          "label": "mech.idler_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "idler_diameter_mm",
          "symbol": "D_I",
          "label": "mech.idler_diameter",
          "unit": "mm",
          "units": true,
          "required": false,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "counterweight_kg",
          "symbol": "m_c",
          "label": "mech.counterweight",
          "unit": "kg",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_force_n",
          "symbol": "F_R",
          "label": "mech.friction_force",
          "unit": "N",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 10000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "rack_pinion",
      "label": "load.rack_pinion",
      "hint": "mech.rack_pinion.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": true,
      "transmission": true,
      "fields": [
        {
          "name": "mass_kg",
          "symbol": "m",
          "label": "mech.mass",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "pinion_diameter_mm",
          "symbol": "d",
          "label": "mech.pinion_diameter",
          "unit": "mm",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "incline_deg",
          "symbol": "θ",
          "label": "mech.incline",
          "unit": "°",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": -90.0,
          "maximum": 90.0,
          "exclusive_minimum": false
        },
        {
          "name": "pinion_inertia_kgm2",
          "symbol": "J_P",
          "label": "mech.pinion_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "counterweight_kg",
          "symbol": "m_c",
          "label": "mech.counterweight",
          "unit": "kg",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_force_n",
          "symbol": "F_R",
          "label": "mech.friction_force",
          "unit": "N",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 10000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "conveyor",
      "label": "load.conveyor",
      "hint": "mech.conveyor.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": true,
      "transmission": true,
      "fields": [
        {
          "name": "load_mass_kg",
          "symbol": "m",
          "label": "mech.conveyor_load",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "belt_mass_kg",
          "symbol": "m_B",
          "label": "mech.belt_mass",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "roller_diameter_mm",
          "symbol": "D",
          "label": "mech.roller_diameter",
          "unit": "mm",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_coefficient",
          "symbol": "μ",
          "label": "load.friction",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 10.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "incline_deg",
          "symbol": "θ",
          "label": "mech.incline",
          "unit": "°",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": -90.0,
          "maximum": 90.0,
          "exclusive_minimum": false
        },
        {
          "name": "drive_roller_inertia_kgm2",
          "symbol": "J_D",
          "label": "mech.drive_roller_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "tail_roller_inertia_kgm2",
          "symbol": "J_T",
          "label": "mech.tail_roller_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "tail_roller_diameter_mm",
          "symbol": "D_T",
          "label": "mech.tail_roller_diameter",
          "unit": "mm",
          "units": true,
          "required": false,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_force_n",
          "symbol": "F_R",
          "label": "mech.friction_force",
          "unit": "N",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 10000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "lift",
      "label": "load.lift",
      "hint": "mech.lift.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": true,
      "transmission": true,
      "fields": [
        {
          "name": "load_mass_kg",
          "symbol": "m",
          "label": "mech.lift_mass",
          "unit": "kg",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "drum_diameter_mm",
          "symbol": "D",
          "label": "mech.drum_diameter",
          "unit": "mm",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.001,
          "maximum": 100000.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": true,
          "default": null,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        },
        {
          "name": "counterweight_kg",
          "symbol": "m_c",
          "label": "mech.counterweight",
          "unit": "kg",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "drum_inertia_kgm2",
          "symbol": "J_D",
          "label": "mech.drum_inertia",
          "unit": "kgm²",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_force_n",
          "symbol": "F_R",
          "label": "mech.friction_force",
          "unit": "N",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 10000000.0,
          "exclusive_minimum": false
        }
      ]
    },
    {
      "type": "rotary",
      "label": "load.rotary",
      "hint": "mech.rotary.hint",
      "equation": null,
      "speed_field": "speed",
      "linear": false,
      "transmission": true,
      "fields": [
        {
          "name": "inertia_kgm2",
          "symbol": "J",
          "label": "load.inertia",
          "unit": "kgm²",
          "units": true,
          "required": true,
          "default": null,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "friction_torque_nm",
          "symbol": "T_F",
          "label": "mech.friction_torque",
          "unit": "Nm",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": 0.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "gravity_torque_nm",
          "symbol": "T_G",
          "label": "mech.gravity_torque",
          "unit": "Nm",
          "units": true,
          "required": false,
          "default": 0.0,
          "minimum": -1000000.0,
          "maximum": 1000000.0,
          "exclusive_minimum": false
        },
        {
          "name": "efficiency",
          "symbol": "η",
          "label": "load.efficiency",
          "unit": "–",
          "units": false,
          "required": false,
          "default": 1.0,
          "minimum": 0.01,
          "maximum": 1.0,
          "exclusive_minimum": false
        }
      ]
    }
  ],
  "transmission": [
    {
      "name": "ratio",
      "symbol": "i",
      "label": "mech.tr.ratio",
      "unit": "–",
      "units": false,
      "required": true,
      "default": null,
      "minimum": 0.001,
      "maximum": 10000.0,
      "exclusive_minimum": false
    },
    {
      "name": "inertia_kgm2",
      "symbol": "J_tr",
      "label": "mech.tr.inertia",
      "unit": "kgm²",
      "units": true,
      "required": false,
      "default": 0.0,
      "minimum": 0.0,
      "maximum": 1000000.0,
      "exclusive_minimum": false
    },
    {
      "name": "efficiency",
      "symbol": "η_tr",
      "label": "mech.tr.efficiency",
      "unit": "–",
      "units": false,
      "required": false,
      "default": 1.0,
      "minimum": 0.01,
      "maximum": 1.0,
      "exclusive_minimum": false
    }
  ]
};
