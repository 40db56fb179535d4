//! The tokens of a Rust source file that matter to its module paths: identifiers, string
//! literals (for `#[path = "…"]`) and punctuation, with comments, characters and lifetimes
//! dropped.

/// One token.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Token {
    /// An identifier or keyword (`crate`, `super`, `mod`, `use`, a name).
    Ident(String),
    /// A string literal's contents (escapes left as written).
    Str(String),
    /// `::`.
    PathSep,
    /// Any other punctuation character.
    Punct(char),
}

/// The tokens of `text`, each with its line (from 1).
pub fn tokens(text: &str) -> Vec<(Token, usize)> {
    let c: Vec<char> = text.chars().collect();
    let mut line_of = Vec::with_capacity(c.len());
    let mut line = 1;
    for &ch in &c {
        line_of.push(line);
        line += usize::from(ch == '\n');
    }
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        let at = line_of[i];
        let ch = c[i];
        let next = c.get(i + 1).copied();
        if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && next == Some('*') {
            i = skip_block_comment(&c, i);
        } else if let Some((end, s)) = string_at(&c, i) {
            out.push((Token::Str(s), at));
            i = end;
        } else if ch == '\'' {
            i = skip_char_or_lifetime(&c, i);
        } else if ch.is_alphanumeric() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push((Token::Ident(c[start..i].iter().collect()), at));
        } else if ch == ':' && next == Some(':') {
            out.push((Token::PathSep, at));
            i += 2;
        } else {
            out.push((Token::Punct(ch), at));
            i += 1;
        }
    }
    out
}

/// The index after the (nested) block comment opening at `i`.
fn skip_block_comment(c: &[char], mut i: usize) -> usize {
    let mut depth = 0;
    while i < c.len() {
        if c[i] == '/' && c.get(i + 1) == Some(&'*') {
            depth += 1;
            i += 2;
        } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return i;
            }
        } else {
            i += 1;
        }
    }
    i
}

/// A string literal (plain, byte, raw, C) opening at `i`: the index after it and its contents.
fn string_at(c: &[char], i: usize) -> Option<(usize, String)> {
    // An identifier ending just before `i` (as in `br`) is not a prefix here.
    if i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_') {
        return None;
    }
    let mut j = i;
    while j < c.len() && j < i + 2 && matches!(c[j], 'b' | 'c' | 'r') {
        j += 1;
    }
    let raw = c[i..j].contains(&'r');
    let mut hashes = 0;
    while raw && c.get(j) == Some(&'#') {
        hashes += 1;
        j += 1;
    }
    if c.get(j) != Some(&'"') {
        return None;
    }
    let start = j + 1;
    let mut k = start;
    while k < c.len() {
        if !raw && c[k] == '\\' {
            k += 2;
            continue;
        }
        if c[k] == '"' && (0..hashes).all(|h| c.get(k + 1 + h) == Some(&'#')) {
            return Some((k + 1 + hashes, c[start..k].iter().collect()));
        }
        k += 1;
    }
    Some((c.len(), c[start..].iter().collect()))
}

/// The index after a character literal or a lifetime opening at `i` (`'`).
fn skip_char_or_lifetime(c: &[char], i: usize) -> usize {
    if c.get(i + 1) == Some(&'\\') {
        let mut k = i + 2;
        while k < c.len() && c[k] != '\'' {
            k += 1;
        }
        return k + 1;
    }
    if c.get(i + 2) == Some(&'\'') {
        return i + 3;
    }
    // A lifetime or label: the quote and the identifier after it.
    let mut k = i + 1;
    while k < c.len() && (c[k].is_alphanumeric() || c[k] == '_') {
        k += 1;
    }
    k
}
