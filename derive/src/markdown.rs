//! The shape of the Markdown the generator writes (issue 32, item 4: no
//! line of docs/*.md longer than 400 characters): prose broken into lines
//! of at most [`WIDTH`] characters at spaces; a display formula longer
//! than [`LONGEST`] broken at spaces into lines of about [`WIDTH`] (a
//! newline is a space in TeX's math mode, so the formula reads the same);
//! a table row longer than [`LONGEST`] with its long cells cut to
//! [`MAX_CELL`] characters and a numbered reference to the cell's full
//! text in a last section, "Details in full". Code blocks, headings and
//! short table rows are left as they are.
//!
//! Owns: [`tidy`], [`wrap_prose`]. May use: std only.

/// The width prose is broken at.
pub const WIDTH: usize = 110;
/// The longest line a document may keep.
pub const LONGEST: usize = 400;
/// The longest cell of a table row that was too long.
pub const MAX_CELL: usize = 120;

/// `doc` with every line at most [`LONGEST`] characters (a single word
/// longer than that aside), as the module says.
pub fn tidy(doc: &str) -> String {
    let mut notes: Vec<String> = Vec::new();
    let mut out = String::new();
    let mut in_code = false;
    for line in doc.split_inclusive('\n') {
        let body = line.trim_end_matches('\n');
        let newline = if line.ends_with('\n') { "\n" } else { "" };
        if body.trim_start().starts_with("```") {
            in_code = !in_code;
            out.push_str(line);
            continue;
        }
        if in_code || body.starts_with('#') {
            out.push_str(line);
            continue;
        }
        if body.starts_with('|') {
            if body.chars().count() <= LONGEST {
                out.push_str(line);
            } else {
                out.push_str(&short_cells(body, &mut notes));
                out.push_str(newline);
            }
            continue;
        }
        if body.starts_with("$$") {
            if body.chars().count() <= LONGEST {
                out.push_str(line);
            } else {
                out.push_str(&break_at_spaces(body, WIDTH, |_| false));
                out.push_str(newline);
            }
            continue;
        }
        out.push_str(&wrap_prose(line, WIDTH));
    }
    if !notes.is_empty() {
        if !out.ends_with('\n') {
            out.push('\n');
        }
        out.push_str(
            "\n## Details in full\n\nThe table cells above that end in a number say it in full here.\n",
        );
        for (i, t) in notes.iter().enumerate() {
            out.push('\n');
            out.push_str(&wrap_prose(
                &format!("{}. {}", i + 1, t.replace("\\|", "|")),
                WIDTH,
            ));
            out.push('\n');
        }
    }
    out
}

/// A table row with each cell longer than [`MAX_CELL`] cut at a space and
/// ended by a reference to its full text, which is added to `notes` (a
/// text already there keeps its number).
fn short_cells(row: &str, notes: &mut Vec<String>) -> String {
    let cells: Vec<String> = row
        .trim_start_matches("| ")
        .trim_end_matches(" |")
        .split(" | ")
        .map(|c| {
            if c.chars().count() <= MAX_CELL {
                return c.to_string();
            }
            let n = match notes.iter().position(|t| t == c) {
                Some(i) => i + 1,
                None => {
                    notes.push(c.to_string());
                    notes.len()
                }
            };
            let suffix = format!(" … [{n}](#details-in-full)");
            let keep = MAX_CELL - suffix.chars().count();
            let mut cut: String = c.chars().take(keep).collect();
            if let Some(i) = cut.rfind(' ') {
                cut.truncate(i);
            }
            // an escaped bar must not lose its backslash's partner, nor a
            // code span its closing backtick
            cut = cut.trim_end_matches('\\').to_string();
            if cut.matches('`').count() % 2 == 1 {
                cut.push('`');
            }
            cut + suffix.as_str()
        })
        .collect();
    format!("| {} |", cells.join(" | "))
}

/// Markdown prose broken into lines of at most `width` characters at
/// spaces (a paragraph reads the same); table rows, display math and
/// headings are left as they are.
pub fn wrap_prose(text: &str, width: usize) -> String {
    let mut out = String::new();
    for line in text.split_inclusive('\n') {
        let body = line.trim_end_matches('\n');
        let keep = body.chars().count() <= width
            || body.starts_with('|')
            || body.starts_with("$$")
            || body.starts_with('#');
        if keep {
            out.push_str(line);
            continue;
        }
        out.push_str(&break_at_spaces(body, width, starts_block));
        if line.ends_with('\n') {
            out.push('\n');
        }
    }
    out
}

/// Whether a word at the start of a line would make Markdown read a block
/// there: a list marker, a heading, a quote, a table row, a rule.
fn starts_block(w: &str) -> bool {
    matches!(w, "-" | "+" | "*" | "#" | ">" | "|" | "=")
        || w.starts_with('#')
        || w.starts_with('|')
        || w.strip_suffix(['.', ')'])
            .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()))
}

/// `body` broken at spaces into lines of at most `width` characters (a
/// longer word stays whole), never before a word `keep_on_line` names.
fn break_at_spaces(body: &str, width: usize, keep_on_line: impl Fn(&str) -> bool) -> String {
    let mut out = String::new();
    let mut current = String::new();
    for word in body.split(' ') {
        if !current.is_empty()
            && current.chars().count() + 1 + word.chars().count() > width
            && !keep_on_line(word)
        {
            out.push_str(&current);
            out.push('\n');
            current.clear();
        }
        if !current.is_empty() {
            current.push(' ');
        }
        current.push_str(word);
    }
    out.push_str(&current);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_lines_are_broken_and_nothing_else_changes() {
        let prose = "word ".repeat(100);
        let formula = format!("$$ {} $$", "x + ".repeat(150));
        let row = format!("| a | {} | b |", "long cell ".repeat(50));
        let doc = format!(
            "# A heading that stays\n\n{prose}\n\n{formula}\n\n| a | b | c |\n|---|---|---|\n{row}\n\n```\n{}\n```\n",
            "code ".repeat(100)
        );
        let out = tidy(&doc);
        let code_line = "code ".repeat(100);
        for l in out.lines() {
            assert!(
                l.chars().count() <= LONGEST || l == code_line,
                "{} characters: {l}",
                l.chars().count()
            );
        }
        // the words, the formula and the cell's text are all still there
        let words = |s: &str| s.split_whitespace().filter(|w| *w == "word").count();
        assert_eq!(words(&out), 100);
        assert_eq!(out.split_whitespace().filter(|w| *w == "x").count(), 150);
        assert_eq!(out.split_whitespace().filter(|w| *w == "$$").count(), 2);
        assert!(out.contains("\n$$ x + x"));
        let details = &out[out.find("## Details in full").expect("a last section")..];
        assert_eq!(
            details.split_whitespace().filter(|w| *w == "cell").count(),
            50,
            "{details}"
        );
        assert!(out.contains(" … [1](#details-in-full) | b |"));
        assert!(out.contains("# A heading that stays\n") && out.contains("| a | b | c |\n"));
        // idempotent: a tidy document stays as it is
        assert_eq!(tidy(&out), out);
    }
}
