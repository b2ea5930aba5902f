//! Every relative link of the project's Markdown resolves: the top-level pages (README.md,
//! ARCHITECTURE.md), the manual under `docs/` and each crate's README. A link's file or folder
//! exists beside the page that names it, and its `#anchor`, when it points into a Markdown page
//! (or into the same page), is one that a heading of that page makes by GitHub's rule. Links
//! inside code, fenced blocks or inline spans, are examples and are not checked. Addresses with
//! a scheme (`https:`, `mailto:`) are left to the reader.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

/// The repository's root: this file is registered as a test of a crate two folders below it.
fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A link on a page: its target as written, and the line it is on.
#[derive(Debug)]
struct Link {
    line: usize,
    target: String,
}

/// The pages checked: the root's Markdown, the manual's at any depth, and each crate's README.
fn markdown_pages(root: &Path) -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = entries(root)
        .into_iter()
        .filter(|p| is_markdown(p))
        .collect();
    collect_markdown(&root.join("docs"), &mut pages);
    for krate in entries(&root.join("crates")) {
        let readme = krate.join("README.md");
        if readme.is_file() {
            pages.push(readme);
        }
    }
    pages
}

/// The Markdown files under `dir`, in name order, depth first.
fn collect_markdown(dir: &Path, pages: &mut Vec<PathBuf>) {
    for path in entries(dir) {
        if path.is_dir() {
            collect_markdown(&path, pages);
        } else if is_markdown(&path) {
            pages.push(path);
        }
    }
}

/// A folder's entries in name order (none when it cannot be read), so that problems are listed
/// in the same order on every machine.
fn entries(dir: &Path) -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = match fs::read_dir(dir) {
        Ok(read) => read.filter_map(Result::ok).map(|e| e.path()).collect(),
        Err(_) => Vec::new(),
    };
    paths.sort();
    paths
}

fn is_markdown(path: &Path) -> bool {
    path.is_file() && path.extension().and_then(|e| e.to_str()) == Some("md")
}

/// The links and images of a page, `[text](target)` and `![alt](target)`, outside code.
fn links(text: &str) -> Vec<Link> {
    let chars = without_code_spans(&without_fences(text));
    let mut found = Vec::new();
    let mut i = 0;
    while i + 1 < chars.len() {
        if chars[i] == ']'
            && chars[i + 1] == '('
            && opening_bracket(&chars, i).is_some()
            && let Some(close) = closing_paren(&chars, i + 1)
        {
            let inside: String = chars[i + 2..close].iter().collect();
            found.push(Link {
                line: line_of(&chars, i),
                target: destination(&inside),
            });
            i = close;
        }
        i += 1;
    }
    found
}

/// The `[` that the `]` at `close` ends, within the same paragraph (text may wrap lines).
fn opening_bracket(chars: &[char], close: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut line_blank_so_far = false;
    for (j, &c) in chars[..close].iter().enumerate().rev() {
        match c {
            ']' => depth += 1,
            '[' if depth == 0 => return Some(j),
            '[' => depth -= 1,
            '\n' if line_blank_so_far => return None,
            '\n' => line_blank_so_far = true,
            _ => {}
        }
        if !c.is_whitespace() {
            line_blank_so_far = false;
        }
    }
    None
}

/// The `)` that closes the `(` at `open` on the same line; targets may hold balanced brackets.
fn closing_paren(chars: &[char], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (j, &c) in chars.iter().enumerate().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(j);
                }
            }
            '\n' => return None,
            _ => {}
        }
    }
    None
}

/// The destination in a link's brackets: `<with spaces>` or the first word (a title may follow).
fn destination(inside: &str) -> String {
    let inside = inside.trim();
    if let Some(rest) = inside.strip_prefix('<')
        && let Some(end) = rest.find('>')
    {
        return rest[..end].to_string();
    }
    inside.split_whitespace().next().unwrap_or("").to_string()
}

/// The one-based line of the character at `at`.
fn line_of(chars: &[char], at: usize) -> usize {
    chars[..at].iter().filter(|&&c| c == '\n').count() + 1
}

/// `text` with its fenced code blocks (``` or ~~~, fences included) blanked: every character
/// but a line break becomes a space, so that lines keep their numbers.
fn without_fences(text: &str) -> Vec<char> {
    let mut out = Vec::with_capacity(text.len());
    let mut open: Option<(char, usize)> = None;
    for line in text.split_inclusive('\n') {
        let blank = match (open, fence(line)) {
            (None, Some(opening)) => {
                open = Some(opening);
                true
            }
            (Some((c, n)), Some((d, m)))
                if c == d && m >= n && line.trim().chars().all(|x| x == c) =>
            {
                open = None;
                true
            }
            (Some(_), _) => true,
            (None, None) => false,
        };
        out.extend(
            line.chars()
                .map(|c| if blank && c != '\n' { ' ' } else { c }),
        );
    }
    out
}

/// The character and length of the fence a line starts with, if it starts with one.
fn fence(line: &str) -> Option<(char, usize)> {
    let trimmed = line.trim_start();
    let c = trimmed.chars().next()?;
    if c != '`' && c != '~' {
        return None;
    }
    let n = trimmed.chars().take_while(|&x| x == c).count();
    if n >= 3 { Some((c, n)) } else { None }
}

/// `chars` with its inline code spans blanked: a run of backticks up to the next run of the same
/// length in the same paragraph. A run that nothing closes is literal text, as in CommonMark.
fn without_code_spans(chars: &[char]) -> Vec<char> {
    let mut out = chars.to_vec();
    let mut i = 0;
    while i < chars.len() {
        if chars[i] != '`' {
            i += 1;
            continue;
        }
        let n = backticks_at(chars, i);
        match closing_backticks(chars, i + n, n) {
            Some(close) => {
                for c in &mut out[i..close + n] {
                    if *c != '\n' {
                        *c = ' ';
                    }
                }
                i = close + n;
            }
            None => i += n,
        }
    }
    out
}

/// How many backticks start at `at`.
fn backticks_at(chars: &[char], at: usize) -> usize {
    chars[at..].iter().take_while(|&&c| c == '`').count()
}

/// Where the next run of exactly `n` backticks from `from` starts, before a blank line ends the
/// paragraph.
fn closing_backticks(chars: &[char], from: usize, n: usize) -> Option<usize> {
    let mut j = from;
    let mut line_blank_so_far = false;
    while j < chars.len() {
        match chars[j] {
            '`' => {
                let m = backticks_at(chars, j);
                if m == n {
                    return Some(j);
                }
                line_blank_so_far = false;
                j += m;
                continue;
            }
            '\n' if line_blank_so_far => return None,
            '\n' => line_blank_so_far = true,
            c if !c.is_whitespace() => line_blank_so_far = false,
            _ => {}
        }
        j += 1;
    }
    None
}

/// The anchors a page's headings make, in order; GitHub numbers a repeated one `-1`, `-2`…
fn anchors(text: &str) -> Vec<String> {
    let text: String = without_fences(text).into_iter().collect();
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut out = Vec::new();
    for line in text.lines() {
        let Some(heading) = heading_text(line) else {
            continue;
        };
        let anchor = github_anchor(heading);
        let count = seen.entry(anchor.clone()).or_insert(0);
        out.push(if *count == 0 {
            anchor
        } else {
            format!("{anchor}-{count}")
        });
        *count += 1;
    }
    out
}

/// The text of an ATX heading (`## Text`, an optional closing run of `#` dropped). The pages'
/// headings are plain text and code spans; a link or emphasis in one would need rendering first.
fn heading_text(line: &str) -> Option<&str> {
    let indent = line.len() - line.trim_start_matches(' ').len();
    if indent > 3 {
        return None;
    }
    let rest = &line[indent..];
    let level = rest.len() - rest.trim_start_matches('#').len();
    if !(1..=6).contains(&level) {
        return None;
    }
    let text = &rest[level..];
    if !text.is_empty() && !text.starts_with([' ', '\t']) {
        return None;
    }
    let text = text.trim();
    let before_closing = text.trim_end_matches('#');
    if before_closing.is_empty() || before_closing.ends_with(' ') {
        Some(before_closing.trim_end())
    } else {
        Some(text)
    }
}

/// GitHub's anchor for a heading: lower case; every character but letters (any script), digits,
/// spaces, hyphens and underscores removed; each space a hyphen.
fn github_anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|&c| c.is_alphanumeric() || c == ' ' || c == '-' || c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// Whether a target is an address with a scheme (`https:`, `mailto:`), not a path.
fn has_scheme(target: &str) -> bool {
    let Some(colon) = target.find(':') else {
        return false;
    };
    let scheme = &target[..colon];
    scheme.starts_with(|c: char| c.is_ascii_alphabetic())
        && scheme
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'))
}

/// What is wrong with a link from `page` to `target`, if anything. `anchors_of` keeps each
/// page's anchors once they are read.
fn problem(
    root: &Path,
    page: &Path,
    target: &str,
    anchors_of: &mut HashMap<PathBuf, Vec<String>>,
) -> Option<String> {
    if target.is_empty() {
        return Some("empty target".to_string());
    }
    if has_scheme(target) {
        return None;
    }
    let (path, anchor) = match target.split_once('#') {
        Some((path, anchor)) => (path, anchor),
        None => (target, ""),
    };
    let path = path.split('?').next().unwrap_or(path);
    let file = if path.is_empty() {
        page.to_path_buf()
    } else if let Some(from_root) = path.strip_prefix('/') {
        root.join(from_root)
    } else {
        page.parent().unwrap_or(root).join(path)
    };
    if !file.exists() {
        return Some("no such file or folder".to_string());
    }
    if anchor.is_empty() || !is_markdown(&file) {
        return None;
    }
    let key = fs::canonicalize(&file).unwrap_or_else(|_| file.clone());
    let known = anchors_of
        .entry(key)
        .or_insert_with(|| anchors(&fs::read_to_string(&file).unwrap_or_default()));
    if known.iter().any(|a| a == anchor) {
        None
    } else {
        Some(format!("no heading makes #{anchor}"))
    }
}

/// A page's path as the problem list shows it: from the repository's root.
fn shown(root: &Path, page: &Path) -> String {
    page.strip_prefix(root)
        .unwrap_or(page)
        .display()
        .to_string()
}

#[test]
fn every_relative_link_resolves() {
    let root = repo_root();
    let pages = markdown_pages(&root);
    assert!(
        pages.iter().any(|p| p.ends_with("docs/README.md")),
        "the manual's index, docs/README.md, is missing under {}",
        root.display()
    );
    let mut anchors_of = HashMap::new();
    let mut problems = Vec::new();
    for page in &pages {
        let text = fs::read_to_string(page)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", page.display()));
        for link in links(&text) {
            if let Some(why) = problem(&root, page, &link.target, &mut anchors_of) {
                problems.push(format!(
                    "{}:{}: {} ({why})",
                    shown(&root, page),
                    link.line,
                    link.target
                ));
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} broken links:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The web page links to the project's home page by anchor (`@INERTIA_LAB_URL@#the-app`): README
/// keeps a heading that makes each one.
#[test]
fn the_web_pages_anchors_into_readme_exist() {
    let root = repo_root();
    let page = fs::read_to_string(root.join("web/index.html")).expect("web/index.html reads");
    let readme = anchors(&fs::read_to_string(root.join("README.md")).expect("README.md reads"));
    let marker = "@INERTIA_LAB_URL@#";
    let wanted: Vec<&str> = page
        .match_indices(marker)
        .map(|(at, _)| {
            let rest = &page[at + marker.len()..];
            let end = rest
                .find(|c: char| c == '"' || c == '\'' || c.is_whitespace())
                .unwrap_or(rest.len());
            &rest[..end]
        })
        .collect();
    assert!(!wanted.is_empty(), "web/index.html names no README anchor");
    for anchor in wanted {
        assert!(
            readme.iter().any(|a| a == anchor),
            "web/index.html links to README#{anchor}, which no heading of README.md makes"
        );
    }
}

#[test]
fn anchors_follow_githubs_rule() {
    let cases = [
        (
            "## Two commands (fresh Debian 12)",
            "two-commands-fresh-debian-12",
        ),
        ("### `props --json`, schema 4", "props---json-schema-4"),
        (
            "## Mass properties: `inertia-lab props`",
            "mass-properties-inertia-lab-props",
        ),
        ("## The app's frame times", "the-apps-frame-times"),
        (
            "## Example: the Panda's fingers",
            "example-the-pandas-fingers",
        ),
        (
            "## Figures (`crates/py/bench/calls.py`, `crates/py/bench/engines.py`)",
            "figures-cratespybenchcallspy-cratespybenchenginespy",
        ),
        ("## snake_case and Ünïcode ω ##", "snake_case-and-ünïcode-ω"),
    ];
    for (line, anchor) in cases {
        assert_eq!(anchors(line), [anchor], "{line}");
    }
    // Repeated headings are numbered; a `#` without a space, or a line in a fence, is no heading.
    let page = "# A\n## A\n#hashtag\n```\n# B\n```\n### A\n";
    assert_eq!(anchors(page), ["a", "a-1", "a-2"]);
}

#[test]
fn links_in_code_are_not_links() {
    let page = "\
[one](a.md) and ![two](img/b.png \"a title\")
```sh
[three](fenced.md)
```
`[four](span.md)` and ``[five](`double`.md)`` then [six
wrapped](c.md#x)

[seven](<with space.md>) [eight](https://example.com) [no link] (d.md)
";
    let targets: Vec<(usize, String)> = links(page)
        .into_iter()
        .map(|l| (l.line, l.target))
        .collect();
    assert_eq!(
        targets,
        [
            (1, "a.md".to_string()),
            (1, "img/b.png".to_string()),
            (6, "c.md#x".to_string()),
            (8, "with space.md".to_string()),
            (8, "https://example.com".to_string()),
        ]
    );
}

#[test]
fn broken_targets_are_named() {
    let root = repo_root();
    let readme = root.join("README.md");
    let mut anchors_of = HashMap::new();
    let mut check = |target: &str| problem(&root, &readme, target, &mut anchors_of);
    assert_eq!(check("docs/README.md"), None);
    assert_eq!(check("docs/"), None);
    assert_eq!(check("#two-commands-fresh-debian-12"), None);
    assert_eq!(
        check("docs/README.md#no-such-heading").as_deref(),
        Some("no heading makes #no-such-heading")
    );
    assert_eq!(
        check("#no-such-heading").as_deref(),
        Some("no heading makes #no-such-heading")
    );
    assert_eq!(
        check("docs/no-such-page.md").as_deref(),
        Some("no such file or folder")
    );
    assert_eq!(check("mailto:someone@example.com"), None);
    assert_eq!(check("").as_deref(), Some("empty target"));
}
