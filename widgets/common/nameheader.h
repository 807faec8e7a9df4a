// SPDX-License-Identifier: MIT
#pragma once

#include <QHeaderView>

class QTableView;

/// A table's column titles that say the prefix a name column leaves out: when the rows of a
/// NameDelegate column share leading namespaces and the column is too narrow for whole names, the
/// rows show the rest (NameDelegate::strippedPrefix()) and the title reads `Topic in /a/b/`, the
/// full prefix in its tooltip. Other columns' titles are the model's.
class NameHeader : public QHeaderView
{
    Q_OBJECT
public:
    explicit NameHeader(QWidget* parent = nullptr);
    /// Puts a NameHeader in place of the table's horizontal header (its state kept), once.
    static NameHeader* install(QTableView* table);

    /// The title of `logicalIndex` as shown: the model's, with the stripped prefix when there is one.
    QString title(int logicalIndex) const;

protected:
    void initStyleOptionForIndex(QStyleOptionHeader* option, int logicalIndex) const override;
    bool viewportEvent(QEvent* event) override;

private:
    QString strippedPrefix(int logicalIndex) const;
};
