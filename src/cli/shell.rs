//! Command lines as a shell reads them: words single-quoted where needed.

/// `words` joined by spaces, each single-quoted unless it is plain (letters, digits, `-_./=:,+`).
pub fn shell_line<S: AsRef<str>>(words: impl IntoIterator<Item = S>) -> String {
    words
        .into_iter()
        .map(|w| {
            let w = w.as_ref();
            if !w.is_empty()
                && w.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c))
            {
                w.to_string()
            } else {
                format!("'{}'", w.replace('\'', "'\\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::shell_line;

    #[test]
    fn words_with_spaces_or_quotes_are_quoted() {
        let line = shell_line(["platefall", "free", "--polygon", "my wedge.txt", "it's", ""]);
        assert_eq!(
            line,
            r#"platefall free --polygon 'my wedge.txt' 'it'\''s' ''"#
        );
    }
}
