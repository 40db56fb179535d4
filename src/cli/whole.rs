//! Whole-number options (counts, resolutions, threads, seeds) given a negative number: clap would
//! read "-16" as an unknown flag ("unexpected argument"); here it is taken as the option's value
//! and refused by name, with what is accepted.
use clap::builder::ValueParser;
use clap::{value_parser, Arg, Command};

/// `cmd` and its subcommands with every whole-number option taking negative values, which its
/// parser refuses with the accepted range.
pub fn negatives_named(cmd: Command) -> Command {
    cmd.mut_args(with_negatives)
        .mut_subcommands(negatives_named)
}

fn with_negatives(arg: Arg) -> Arg {
    let id = arg.get_value_parser().type_id();
    let of = |p: ValueParser| p.type_id();
    let parser: ValueParser = if id == of(value_parser!(usize).into()) {
        parse::<usize>.into()
    } else if id == of(value_parser!(u64).into()) {
        parse::<u64>.into()
    } else if id == of(value_parser!(u32).into()) {
        parse::<u32>.into()
    } else {
        return arg;
    };
    arg.allow_negative_numbers(true).value_parser(parser)
}

/// A whole number of type `T`; a negative one is named as such (the option's own range, where it
/// has one, is checked with the rest of the run's description and stated in its `--help`).
fn parse<T>(text: &str) -> Result<T, String>
where
    T: std::str::FromStr,
    T::Err: std::fmt::Display,
{
    let text = text.trim();
    if text.parse::<i128>().is_ok_and(|v| v < 0) {
        return Err(format!(
            "{text} is negative: accepted a whole number, 0 or more (--help gives the option's range)"
        ));
    }
    text.parse::<T>().map_err(|e| e.to_string())
}
