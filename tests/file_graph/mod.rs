//! The file graph of a crate: its module tree, read from `mod` declarations from the crate root,
//! and an arrow from file A to file B wherever A names a path (`use crate::…`, `super::…`,
//! `self::…`, a child module, in a `use` or in code) that leads to B: to the file that defines
//! the item it names, following `use` re-exports (`pub use child::Item` in a `mod.rs` makes a
//! sibling's `super::Item` an arrow to the child, and the re-export an arrow from the `mod.rs`
//! to the child), or to the module's file when it names a module. Declaring a module is not
//! using it, and unit tests (`#[cfg(test)]` modules and imports) are left out: like the tests
//! under `tests/`, they may use any file of their crate.
mod cycles;
mod lex;
mod parse;

pub use cycles::circles;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use parse::{parse, Binding, Parsed};

/// A module: the file its body is in, its parent and its children by name (a name may have
/// two files under different `cfg`s).
struct Module {
    file: usize,
    parent: Option<usize>,
    children: Vec<(String, usize)>,
    /// The items it defines.
    defs: BTreeSet<String>,
    /// Its `use` leaves: the path and what it binds.
    imports: Vec<(Vec<String>, Binding)>,
    /// Whether it is compiled for unit tests only (it or a module around it is `#[cfg(test)]`).
    test: bool,
}

impl Module {
    fn new(file: usize, parent: Option<usize>) -> Module {
        Module {
            file,
            parent,
            children: Vec::new(),
            defs: BTreeSet::new(),
            imports: Vec::new(),
            test: false,
        }
    }
}

/// The files of a crate and the arrows between them.
pub struct FileGraph {
    /// Each file, relative to the workspace root.
    pub files: Vec<String>,
    /// For each arrow (from, to) between file indices, the first line of `from` that names `to`.
    pub arrows: BTreeMap<(usize, usize), (usize, String)>,
    /// The files compiled for unit tests only (declared under `#[cfg(test)]`, or inside such a
    /// module).
    pub unit_test_files: BTreeSet<String>,
}

impl FileGraph {
    /// The graph as names: each file with the files it uses.
    pub fn named(&self) -> BTreeMap<String, BTreeSet<String>> {
        let mut out: BTreeMap<String, BTreeSet<String>> = self
            .files
            .iter()
            .map(|f| (f.clone(), BTreeSet::new()))
            .collect();
        for &(a, b) in self.arrows.keys() {
            out.get_mut(&self.files[a])
                .expect("file")
                .insert(self.files[b].clone());
        }
        out
    }

    /// Why `from` uses `to`: "from:line names path".
    pub fn evidence(&self, from: &str, to: &str) -> String {
        let index = |f: &str| self.files.iter().position(|g| g == f);
        match (index(from), index(to)) {
            (Some(a), Some(b)) => match self.arrows.get(&(a, b)) {
                Some((line, path)) => format!("{from}:{line} names {path}"),
                None => format!("{from} (no arrow to {to})"),
            },
            _ => format!("{from} (unknown file)"),
        }
    }
}

/// The file graph of the crate whose root file is `root` (e.g. `crates/x/src/lib.rs`, relative
/// to `workspace`).
pub fn crate_graph(workspace: &Path, root: &str) -> FileGraph {
    let mut files: Vec<PathBuf> = Vec::new();
    let mut parsed: Vec<Parsed> = Vec::new();
    let mut modules = vec![Module::new(0, None)];
    // (file index, module of the file's top level)
    let mut queue = vec![(workspace.join(root), 0usize)];
    while let Some((path, top)) = queue.pop() {
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let file = files.len();
        files.push(path.clone());
        modules[top].file = file;
        let p = parse(&text);
        for d in &p.decls {
            let at = scope_module(&modules, top, &d.scope);
            let child = modules.len();
            let mut module = Module::new(file, Some(at));
            module.test = d.test || modules[at].test;
            modules.push(module);
            modules[at].children.push((d.name.clone(), child));
            if !d.inline {
                queue.push((
                    child_file(&path, &d.scope, &d.name, d.path_attr.as_deref()),
                    child,
                ));
            }
        }
        parsed.push(p);
    }
    let mut arrows = BTreeMap::new();
    let file_top: Vec<usize> = (0..files.len())
        .map(|f| {
            (0..modules.len())
                .find(|&m| {
                    modules[m].file == f && modules[m].parent.is_none_or(|p| modules[p].file != f)
                })
                .expect("each file is a module")
        })
        .collect();
    for (f, p) in parsed.iter().enumerate() {
        for d in &p.defs {
            let m = scope_module(&modules, file_top[f], &d.scope);
            modules[m].defs.insert(d.name.clone());
        }
        for r in &p.refs {
            if let Some(b) = &r.binding {
                let m = scope_module(&modules, file_top[f], &r.scope);
                modules[m].imports.push((r.segments.clone(), b.clone()));
            }
        }
    }
    for (f, p) in parsed.iter().enumerate() {
        for r in &p.refs {
            let from = scope_module(&modules, file_top[f], &r.scope);
            if modules[from].test {
                continue;
            }
            for g in resolve(&modules, from, &r.segments, 0) {
                if g != f {
                    arrows
                        .entry((f, g))
                        .or_insert_with(|| (r.line, r.segments.join("::")));
                }
            }
        }
    }
    let rel = |p: &PathBuf| p.strip_prefix(workspace).unwrap_or(p).display().to_string();
    let unit_test_files = (0..files.len())
        .filter(|&f| modules[file_top[f]].test)
        .map(|f| rel(&files[f]))
        .collect();
    FileGraph {
        files: files.iter().map(rel).collect(),
        arrows,
        unit_test_files,
    }
}

/// The inline module `scope` inside module `top` (declared before, so present).
fn scope_module(modules: &[Module], top: usize, scope: &[String]) -> usize {
    scope.iter().fold(top, |m, name| {
        modules[m]
            .children
            .iter()
            .rev()
            .find(|(n, c)| n == name && modules[*c].file == modules[m].file)
            .map_or(m, |&(_, c)| c)
    })
}

/// The file of module `name` declared in `parent` inside the inline modules `scope`.
fn child_file(parent: &Path, scope: &[String], name: &str, path_attr: Option<&str>) -> PathBuf {
    let dir = parent.parent().expect("a file has a directory");
    let stem = parent
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or_default();
    let mut base = if matches!(stem, "lib" | "main" | "mod") || path_attr.is_some() {
        dir.to_path_buf()
    } else {
        dir.join(stem)
    };
    for s in scope {
        base.push(s);
    }
    if let Some(p) = path_attr {
        return base.join(p);
    }
    let flat = base.join(format!("{name}.rs"));
    if flat.is_file() {
        flat
    } else {
        base.join(name).join("mod.rs")
    }
}

/// How deep re-exports are followed (a bound on circles of globs).
const MAX_DEPTH: usize = 8;

/// The modules a path written in module `from` walks through as far as its segments name
/// modules, and how many segments that took (0: the path leaves the crate).
fn walk(modules: &[Module], from: usize, segments: &[String]) -> (Vec<usize>, usize) {
    let children = |m: usize, name: &str| -> Vec<usize> {
        modules[m]
            .children
            .iter()
            .filter(|(n, _)| n == name)
            .map(|&(_, c)| c)
            .collect()
    };
    let Some(first) = segments.first() else {
        return (Vec::new(), 0);
    };
    let mut current = match first.as_str() {
        "crate" => {
            let mut m = from;
            while let Some(p) = modules[m].parent {
                m = p;
            }
            vec![m]
        }
        "self" => vec![from],
        "super" => modules[from].parent.into_iter().collect(),
        name => children(from, name),
    };
    if current.is_empty() {
        return (Vec::new(), 0);
    }
    let mut used = 1;
    for s in &segments[1..] {
        let next: Vec<usize> = if s == "super" {
            current.iter().filter_map(|&m| modules[m].parent).collect()
        } else {
            current.iter().flat_map(|&m| children(m, s)).collect()
        };
        if next.is_empty() {
            break;
        }
        current = next;
        used += 1;
    }
    (current, used)
}

/// The files a path written in module `from` leads to: the file of the module it names, or of
/// the item it names inside a module (following re-exports); none for a path outside the crate.
fn resolve(modules: &[Module], from: usize, segments: &[String], depth: usize) -> BTreeSet<usize> {
    let (reached, used) = walk(modules, from, segments);
    match segments.get(used) {
        _ if reached.is_empty() => BTreeSet::new(),
        // The rest names an item of the modules reached (and perhaps a member of it).
        Some(item) => reached
            .iter()
            .flat_map(|&m| item_files(modules, m, item, depth))
            .collect(),
        None => reached.iter().map(|&m| modules[m].file).collect(),
    }
}

/// Whether module `m` has `name` of its own or by a named import.
fn has(modules: &[Module], m: usize, name: &str) -> bool {
    let named = Binding::Name(name.to_string());
    modules[m].defs.contains(name) || modules[m].imports.iter().any(|(_, b)| *b == named)
}

/// The files that define `name` as seen from module `m`: its own file if it defines it, else
/// where its `use` of that name leads, else where its glob imports of modules that have it lead.
fn item_files(modules: &[Module], m: usize, name: &str, depth: usize) -> BTreeSet<usize> {
    let own = BTreeSet::from([modules[m].file]);
    if modules[m].defs.contains(name) || depth >= MAX_DEPTH {
        return own;
    }
    let named = Binding::Name(name.to_string());
    let mut found: BTreeSet<usize> = modules[m]
        .imports
        .iter()
        .filter(|(_, b)| *b == named)
        .flat_map(|(path, _)| resolve(modules, m, path, depth + 1))
        .collect();
    if found.is_empty() {
        for (path, _) in modules[m]
            .imports
            .iter()
            .filter(|(_, b)| *b == Binding::Glob)
        {
            let (reached, used) = walk(modules, m, path);
            if used == path.len() {
                for g in reached.into_iter().filter(|&g| has(modules, g, name)) {
                    found.extend(item_files(modules, g, name, depth + 1));
                }
            }
        }
    }
    if found.is_empty() {
        own
    } else {
        found
    }
}
