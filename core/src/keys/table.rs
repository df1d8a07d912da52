//! A table's keys as the book's reference lists them: [`Key`] and [`Table`], which the derives of
//! eulerdyn-derive declare for each table of the scene file.

/// One key of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    /// The key as written in the file.
    pub name: &'static str,
    /// What the value is: `number`, `[x, y, z]`, a string from a list, a table…
    pub kind: &'static str,
    /// SI unit (`1` dimensionless, `–` none).
    pub unit: &'static str,
    /// The value when the key is absent (`required` when it may not be).
    pub default: &'static str,
    /// For a position: the point it is measured from and its axes; else empty.
    pub origin: &'static str,
    /// What it means, its bounds.
    pub doc: &'static str,
    /// The table the key holds (a `[section]`, an inline table or an array of tables), listed after its table in
    /// the reference.
    pub table: Option<&'static Table>,
}

/// One table of a scene file and its keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Table {
    /// As written in the file (`[body]`, `[[effect]]`; the top level is empty).
    pub header: &'static str,
    /// What the table is.
    pub about: &'static str,
    /// Its keys, in the order of the file form.
    pub keys: &'static [Key],
    /// The tables of its parts (`part` keys, `keys::Part`), each listed after it in the reference.
    pub parts: &'static [Table],
}

impl Key {
    /// A key of no name, where an array of keys is filled.
    pub(crate) const BLANK: Key = Key {
        name: "",
        kind: "",
        unit: "",
        default: "",
        origin: "",
        doc: "",
        table: None,
    };
}
