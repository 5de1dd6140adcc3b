//! `bumpwork man`: the manual page (roff), made from the same definitions as `--help`
//! (`bumpwork man > bumpwork.1; man ./bumpwork.1`).

use bumpwork::Error;

pub fn run(command: clap::Command) -> Result<(), Error> {
    let mut page = Vec::new();
    clap_mangen::Man::new(command)
        .render(&mut page)
        .expect("writing into memory cannot fail");
    super::write_bytes(&page)
}
