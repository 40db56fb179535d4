//! What one source file says about modules: the modules it declares and the module paths it
//! names (in `use` trees and in code).
use super::lex::{tokens, Token};

/// A `mod NAME;` or `mod NAME { … }` in a file.
#[derive(Debug)]
pub struct Decl {
    /// The inline modules the declaration sits in, outermost first.
    pub scope: Vec<String>,
    /// The module's name.
    pub name: String,
    /// Its `#[path = "…"]` attribute.
    pub path_attr: Option<String>,
    /// Whether its body is in this file (`mod NAME { … }`).
    pub inline: bool,
    /// Whether it is compiled for unit tests only (`#[cfg(test)]`).
    pub test: bool,
}

/// A path a file names that may lead to another module of its crate.
#[derive(Debug)]
pub struct Reference {
    /// The inline modules the path is written in, outermost first.
    pub scope: Vec<String>,
    /// Its segments (`crate`, `super`, `self` or names); a `use` tree gives one per leaf.
    pub segments: Vec<String>,
    /// The line it is written on.
    pub line: usize,
    /// For a `use`: the name it binds in its module.
    pub binding: Option<Binding>,
}

/// What a `use` leaf brings into its module.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Binding {
    /// One name (the last segment, or the `as` name).
    Name(String),
    /// Every public name of the module (`*`).
    Glob,
}

/// An item a file defines (`fn`, `struct`, `enum`, `trait`, `type`, `const`, `static`, `union`,
/// `macro_rules!`), in the inline modules `scope`.
#[derive(Debug)]
pub struct Def {
    /// The inline modules it sits in, outermost first.
    pub scope: Vec<String>,
    /// Its name.
    pub name: String,
}

/// The declarations and references of a file's text.
#[derive(Debug, Default)]
pub struct Parsed {
    /// Modules declared, in order of appearance (outer inline modules before inner ones).
    pub decls: Vec<Decl>,
    /// Paths named.
    pub refs: Vec<Reference>,
    /// Items defined (methods and associated items too: they shadow nothing a path can name).
    pub defs: Vec<Def>,
}

/// Keywords that may stand between an item keyword and a name (`const fn`, `unsafe fn`, …).
const NOT_NAMES: &[&str] = &["fn", "unsafe", "async", "extern", "const", "impl", "mut"];

fn ident(t: Option<&(Token, usize)>) -> Option<&str> {
    match t {
        Some((Token::Ident(s), _)) => Some(s),
        _ => None,
    }
}

fn is(t: Option<&(Token, usize)>, p: char) -> bool {
    matches!(t, Some((Token::Punct(q), _)) if *q == p)
}

fn is_sep(t: Option<&(Token, usize)>) -> bool {
    matches!(t, Some((Token::PathSep, _)))
}

/// Whether tokens from `i` read `#[cfg(test)]`.
fn is_cfg_test(t: &[(Token, usize)], i: usize) -> bool {
    is(t.get(i + 1), '[')
        && ident(t.get(i + 2)) == Some("cfg")
        && is(t.get(i + 3), '(')
        && ident(t.get(i + 4)) == Some("test")
        && is(t.get(i + 5), ')')
}

/// Parses `text`.
pub fn parse(text: &str) -> Parsed {
    let t = tokens(text);
    let mut out = Parsed::default();
    // Open inline modules with the brace depth inside them.
    let mut scope: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut path_attr: Option<String> = None;
    // Whether the next item is `#[cfg(test)]`.
    let mut cfg_test = false;
    let mut i = 0;
    while i < t.len() {
        let names = || scope.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
        match &t[i].0 {
            Token::Punct('{') => {
                depth += 1;
                cfg_test = false;
            }
            Token::Punct('}') => {
                if scope.last().is_some_and(|(_, d)| *d == depth) {
                    scope.pop();
                }
                depth = depth.saturating_sub(1);
                path_attr = None;
                cfg_test = false;
            }
            Token::Punct(';') => {
                path_attr = None;
                cfg_test = false;
            }
            Token::Punct('#') if is_cfg_test(&t, i) => cfg_test = true,
            Token::Punct('#') if is(t.get(i + 1), '[') && ident(t.get(i + 2)) == Some("path") => {
                if let Some((Token::Str(s), _)) = t.get(i + 4) {
                    path_attr = Some(s.clone());
                }
            }
            // A visibility (`pub(crate)`, `pub(in crate::x)`) names no module it uses.
            Token::Ident(k) if k == "pub" && is(t.get(i + 1), '(') => {
                while i < t.len() && !is(t.get(i), ')') {
                    i += 1;
                }
            }
            Token::Ident(k) if k == "mod" => {
                if let Some(name) = ident(t.get(i + 1)) {
                    let inline = is(t.get(i + 2), '{');
                    out.decls.push(Decl {
                        scope: names(),
                        name: name.to_string(),
                        path_attr: path_attr.take(),
                        inline,
                        test: std::mem::take(&mut cfg_test),
                    });
                    if inline {
                        depth += 1;
                        scope.push((name.to_string(), depth));
                        i += 3;
                        continue;
                    }
                }
            }
            Token::Ident(k) if k == "use" => {
                let mut leaves = Vec::new();
                let end = use_tree(&t, i + 1, &[], &mut leaves);
                let line = t[i].1;
                if std::mem::take(&mut cfg_test) {
                    // A unit test's import: tests may use any file of their crate.
                    leaves.clear();
                }
                for (segments, binding) in leaves {
                    out.refs.push(Reference {
                        scope: names(),
                        segments,
                        line,
                        binding: Some(binding),
                    });
                }
                i = end;
                continue;
            }
            Token::Ident(k)
                if matches!(
                    k.as_str(),
                    "fn" | "struct" | "enum" | "trait" | "type" | "const" | "static" | "union"
                ) || (k == "macro_rules" && is(t.get(i + 1), '!')) =>
            {
                let at = if k == "macro_rules" { i + 2 } else { i + 1 };
                if let Some(name) = ident(t.get(at)).filter(|n| !NOT_NAMES.contains(n)) {
                    out.defs.push(Def {
                        scope: names(),
                        name: name.to_string(),
                    });
                }
            }
            Token::Ident(first)
                if is_sep(t.get(i + 1))
                    && !is_sep(i.checked_sub(1).and_then(|k| t.get(k)))
                    && !is(i.checked_sub(1).and_then(|k| t.get(k)), '$') =>
            {
                let mut segments = vec![first.clone()];
                let mut k = i + 1;
                while is_sep(t.get(k)) {
                    match ident(t.get(k + 1)) {
                        Some(s) => segments.push(s.to_string()),
                        None => break,
                    }
                    k += 2;
                }
                out.refs.push(Reference {
                    scope: names(),
                    segments,
                    line: t[i].1,
                    binding: None,
                });
                i = k;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// A `use` leaf: the path and what it binds.
type Leaf = (Vec<String>, Binding);

/// Parses the use tree starting at token `i` below `prefix`, pushing its leaves (`self` in a
/// group is the group's prefix); returns the index after the tree.
fn use_tree(
    t: &[(Token, usize)],
    mut i: usize,
    prefix: &[String],
    leaves: &mut Vec<Leaf>,
) -> usize {
    let mut path = prefix.to_vec();
    let last = |p: &[String]| Binding::Name(p.last().cloned().unwrap_or_default());
    loop {
        match t.get(i).map(|(tok, _)| tok) {
            Some(Token::Ident(s))
                if s == "self" && !prefix.is_empty() && path.len() == prefix.len() =>
            {
                i += 1
            }
            Some(Token::Ident(s)) if s == "as" => {
                let name = ident(t.get(i + 1)).unwrap_or("_").to_string();
                leaves.push((path.clone(), Binding::Name(name)));
                return i + 2;
            }
            Some(Token::Ident(s)) => {
                path.push(s.clone());
                i += 1;
            }
            Some(Token::PathSep) => i += 1,
            Some(Token::Punct('*')) => {
                leaves.push((path.clone(), Binding::Glob));
                return i + 1;
            }
            Some(Token::Punct('{')) => {
                i += 1;
                while i < t.len() && !is(t.get(i), '}') {
                    i = use_tree(t, i, &path, leaves);
                    if is(t.get(i), ',') {
                        i += 1;
                    }
                }
                return i + 1;
            }
            _ => {
                if !path.is_empty() {
                    let b = last(&path);
                    leaves.push((path, b));
                }
                return i;
            }
        }
    }
}
