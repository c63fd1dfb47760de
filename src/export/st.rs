//! `iec61131-st` target: an IEC 61131-3 Structured Text function block with the sampled
//! controller: the statements of [`DiscreteController::step`] (see [`super::sampled`]) on
//! `LREAL` histories, the coefficients as `VAR CONSTANT` arrays (the same literals as the C
//! file), inputs `R`, `Y`, `RESET`, outputs `U` (applied, limited) and `V` (before the limits).
//! Call it once per sample time `H` (a cyclic task with that interval).

use super::sampled::{diff_eq, header as sampled_header, tables};
use super::{comment_lines, header, num, nums, Design};
use crate::model::discrete::{DiscreteController, Law};
use std::fmt::Write;

/// The function block's text. `name` is its identifier (e.g. `PIDLAB_KAYA`).
pub fn write(d: &Design, dc: &DiscreteController, name: &str) -> String {
    let mut h = header(d, "IEC 61131-3 Structured Text function block");
    h.extend(sampled_header(dc));
    h.push(format!(
        "Run {name} in a cyclic task of interval H (if the plant's time unit is not the second, convert)."
    ));
    let eq = diff_eq(dc);
    let n = eq.order();
    let arr = format!("ARRAY[0..{n}] OF LREAL");
    let mut s = String::new();
    let _ = writeln!(s, "FUNCTION_BLOCK {name}");
    s.push_str(&comment_lines(&h, "(* ", &["*)", "(*"]).replace('\n', " *)\n"));
    let _ = write!(
        s,
        r#"VAR_INPUT
    R : LREAL;       (* set point r_k *)
    Y : LREAL;       (* measurement y_k *)
    RESET : BOOL;    (* TRUE: back to rest (all histories zero) before this sample *)
END_VAR
VAR_OUTPUT
    U : LREAL;       (* applied input u_k = sat(V): hold until the next call *)
    V : LREAL;       (* controller output before the limits *)
END_VAR
VAR CONSTANT
    H : LREAL := {h};   (* sample time, plant time unit *)
    (* difference equation, powers of z^-1 (index i: the value i samples ago), A[0] = 1 *)
"#,
        h = num(dc.h)
    );
    for (t, xs) in tables(eq) {
        let _ = writeln!(
            s,
            "    {} : {arr} := [{}];",
            t.to_ascii_uppercase(),
            nums(xs)
        );
    }
    if let Law::Clamped { integrator: ig, .. } = &dc.law {
        let _ = writeln!(
            s,
            "    (* conditional integration: X := X + C0*E + C1*E_PREV, E = G_R*R - G_Y*Y *)"
        );
        let _ = writeln!(s, "    C0 : LREAL := {};", num(ig.c0));
        let _ = writeln!(s, "    C1 : LREAL := {};", num(ig.c1));
        let _ = writeln!(s, "    G_R : LREAL := {};", num(ig.g_r));
        let _ = writeln!(s, "    G_Y : LREAL := {};", num(ig.g_y));
    }
    let (lo, hi) = (dc.limits.u_min, dc.limits.u_max);
    if lo.is_finite() {
        let _ = writeln!(s, "    U_MIN : LREAL := {};", num(lo));
    }
    if hi.is_finite() {
        let _ = writeln!(s, "    U_MAX : LREAL := {};", num(hi));
    }
    let _ = write!(
        s,
        r#"END_VAR
VAR
    RH : {arr};   (* set points, newest first *)
    YH : {arr};   (* measurements *)
    UH : {arr};   (* applied inputs *)
    VH : {arr};   (* outputs of the difference equation *)
    X : LREAL;        (* integral state (conditional integration) *)
    E_PREV : LREAL;
    E : LREAL;
    DX : LREAL;
    VR : LREAL;
    C : LREAL;
    FREE_V : LREAL;
    I : INT;
END_VAR

IF RESET THEN
    FOR I := 0 TO {n} DO
        RH[I] := 0.0;
        YH[I] := 0.0;
        UH[I] := 0.0;
        VH[I] := 0.0;
    END_FOR;
    X := 0.0;
    E_PREV := 0.0;
END_IF;

(* shift the new samples in *)
FOR I := {n} TO 1 BY -1 DO
    RH[I] := RH[I - 1];
    YH[I] := YH[I - 1];
END_FOR;
RH[0] := R;
YH[0] := Y;

(* the terms of the difference equation but B_U[0]*u_k *)
C := 0.0;
FOR I := 0 TO {n} DO
    C := C + (B_R[I] * RH[I] - B_Y[I] * YH[I]);
    IF I >= 1 THEN
        C := C + (B_U[I] * UH[I - 1] - A[I] * VH[I - 1]);
    END_IF;
END_FOR;

"#
    );
    let sat = {
        let mut t = String::from("U := V;\n");
        if lo.is_finite() {
            t.push_str("IF U < U_MIN THEN\n    U := U_MIN;\nEND_IF;\n");
        }
        if hi.is_finite() {
            t.push_str("IF U > U_MAX THEN\n    U := U_MAX;\nEND_IF;\n");
        }
        t
    };
    let shift = |hist: &str, val: &str| {
        format!("FOR I := {n} TO 1 BY -1 DO\n    {hist}[I] := {hist}[I - 1];\nEND_FOR;\n{hist}[0] := {val};\n")
    };
    match &dc.law {
        Law::Linear(eq) => {
            if eq.b_u[0] == 0.0 {
                s.push_str("V := C;\n");
            } else {
                s.push_str("(* V = C + B_U[0]*sat(V), solved exactly (0 <= B_U[0] < 1) *)\n");
                s.push_str("FREE_V := C / (1.0 - B_U[0]);\n");
                let mut branches = vec![];
                if hi.is_finite() {
                    branches.push(("FREE_V > U_MAX", "V := C + B_U[0] * U_MAX;"));
                }
                if lo.is_finite() {
                    branches.push(("FREE_V < U_MIN", "V := C + B_U[0] * U_MIN;"));
                }
                if branches.is_empty() {
                    s.push_str("V := FREE_V;\n");
                } else {
                    for (i, (cond, stmt)) in branches.iter().enumerate() {
                        let kw = if i == 0 { "IF" } else { "ELSIF" };
                        let _ = writeln!(s, "{kw} {cond} THEN\n    {stmt}");
                    }
                    s.push_str("ELSE\n    V := FREE_V;\nEND_IF;\n");
                }
            }
            s.push_str(&sat);
            s.push_str(&shift("VH", "V"));
            s.push_str(&shift("UH", "U"));
        }
        Law::Clamped { .. } => {
            let mut clamp = vec![];
            if hi.is_finite() {
                clamp.push("(V > U_MAX AND DX > 0.0)");
            }
            if lo.is_finite() {
                clamp.push("(V < U_MIN AND DX < 0.0)");
            }
            let cond = if clamp.is_empty() {
                "FALSE".to_string()
            } else {
                clamp.join(" OR ")
            };
            let _ = write!(
                s,
                r#"(* conditional integration: the integral state stops while V is at a limit and its
   increment drives V further out *)
E := G_R * R - G_Y * Y;
DX := C0 * E + C1 * E_PREV;
E_PREV := E;
VR := C;
{shift_v}V := X + DX + VR;
IF NOT ({cond}) THEN
    X := X + DX;
END_IF;
V := X + VR;
{sat}{shift_u}"#,
                shift_v = shift("VH", "VR"),
                shift_u = shift("UH", "U"),
            );
        }
    }
    s.push_str("\nEND_FUNCTION_BLOCK\n");
    s
}
