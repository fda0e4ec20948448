#include "screencheck.h"

#include "widgets/elidedlabel.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QStyleOptionButton>
#include <QStyleOptionComboBox>
#include <QTabBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

namespace tipscope::testing {

using gui::ElidedLabel;

QString shownText(QString text) {
    text.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    return text.replace(QStringLiteral("&&"), QStringLiteral("\x01"))
        .remove(QLatin1Char('&'))
        .replace(QLatin1Char('\x01'), QLatin1Char('&'));
}

QString widgetName(const QWidget *w) {
    return QStringLiteral("%1 %2").arg(QString::fromLatin1(w->metaObject()->className()),
                                       w->objectName());
}

QString clippedText(QWidget *w) {
    if (qobject_cast<ElidedLabel *>(w))
        return {};
    if (auto *label = qobject_cast<QLabel *>(w)) {
        const QString text = shownText(label->text());
        if (text.isEmpty() || label->textFormat() == Qt::RichText)
            return {};
        const QRect room = label->contentsRect();
        if (label->wordWrap()) {
            const int needed = label->heightForWidth(label->width());
            return needed > label->height() + 1
                       ? QStringLiteral("\"%1\" needs %2 px of height, has %3")
                             .arg(text)
                             .arg(needed)
                             .arg(label->height())
                       : QString();
        }
        int width = 0;
        for (const QString &line : text.split(QLatin1Char('\n')))
            width = qMax(width, label->fontMetrics().horizontalAdvance(line));
        return width > room.width() + 1 ? QStringLiteral("\"%1\" needs %2 px, has %3")
                                              .arg(text)
                                              .arg(width)
                                              .arg(room.width())
                                        : QString();
    }
    if (auto *button = qobject_cast<QAbstractButton *>(w)) {
        if (button->text().isEmpty())
            return {};
        // Qt's styles give a push button with text at least 80 px, whatever the text: a short
        // word on a narrower button is still whole. A push button's text is cut where it is
        // wider than the room the style draws it in.
        if (auto *push = qobject_cast<QPushButton *>(button);
            push && push->icon().isNull() && !push->menu()) {
            QStyleOptionButton option;
            option.initFrom(push);
            option.text = push->text();
            const int room =
                push->style()->subElementRect(QStyle::SE_PushButtonContents, &option, push).width();
            const int width = push->fontMetrics().horizontalAdvance(shownText(push->text()));
            return width > room + 1 ? QStringLiteral("\"%1\" needs %2 px, has %3")
                                          .arg(shownText(push->text()))
                                          .arg(width)
                                          .arg(room)
                                    : QString();
        }
        const int needed = button->minimumSizeHint().expandedTo(button->sizeHint()).width();
        return button->width() + 1 < needed ? QStringLiteral("\"%1\" needs %2 px, has %3")
                                                  .arg(shownText(button->text()))
                                                  .arg(needed)
                                                  .arg(button->width())
                                            : QString();
    }
    if (auto *edit = qobject_cast<QLineEdit *>(w)) {
        // The example in an empty field says what to type: cut, it says nothing. Its room ends
        // where the field's own buttons (clear, or a combo box's arrow outside it) begin.
        if (!edit->text().isEmpty() || edit->placeholderText().isEmpty())
            return {};
        QStyleOptionFrame option;
        option.initFrom(edit);
        option.rect = edit->rect();
        option.lineWidth =
            edit->hasFrame()
                ? edit->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, &option, edit)
                : 0;
        QRect room = edit->style()
                         ->subElementRect(QStyle::SE_LineEditContents, &option, edit)
                         .marginsRemoved(edit->textMargins());
        for (const QToolButton *b : edit->findChildren<QToolButton *>())
            if (b->isVisibleTo(edit))
                room.setRight(qMin(room.right(), b->x() - 1));
        const int width = edit->fontMetrics().horizontalAdvance(edit->placeholderText());
        return width > room.width() - 4 ? QStringLiteral("placeholder \"%1\" needs %2 px, has %3")
                                              .arg(edit->placeholderText())
                                              .arg(width)
                                              .arg(room.width() - 4)
                                        : QString();
    }
    if (auto *combo = qobject_cast<QComboBox *>(w)) {
        if (combo->currentText().isEmpty())
            return {};
        QStyleOptionComboBox option;
        option.initFrom(combo);
        option.editable = combo->isEditable();
        const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                           QStyle::SC_ComboBoxEditField, combo);
        const int width = combo->fontMetrics().horizontalAdvance(combo->currentText());
        return width > field.width() + 1 ? QStringLiteral("\"%1\" needs %2 px, has %3")
                                               .arg(combo->currentText())
                                               .arg(width)
                                               .arg(field.width())
                                         : QString();
    }
    if (auto *tabs = qobject_cast<QTabBar *>(w)) {
        QStringList cut;
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->isTabVisible(i) &&
                tabs->tabRect(i).width() + 1 <
                    tabs->fontMetrics().horizontalAdvance(shownText(tabs->tabText(i))) +
                        tabs->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, tabs))
                cut.append(shownText(tabs->tabText(i)));
        return cut.isEmpty() ? QString() : QStringLiteral("tabs cut short: ") + cut.join(", ");
    }
    if (auto *tree = qobject_cast<QTreeWidget *>(w)) {
        QStringList cut;
        for (QTreeWidgetItemIterator it(tree); *it; ++it) {
            const QModelIndex index = tree->indexFromItem(*it);
            const QRect shown = tree->visualRect(index);
            if (shown.isEmpty())
                continue;
            const int needed = tree->sizeHintForIndex(index).width();
            if (shown.right() > tree->viewport()->width() ||
                shown.width() + 1 < needed - tree->indentation())
                cut.append((*it)->text(0));
        }
        return cut.isEmpty() ? QString() : QStringLiteral("entries cut short: ") + cut.join(", ");
    }
    return {};
}

namespace {

// The widgets a layout places, through its nested layouts.
void placedWidgets(QLayout *layout, QList<QWidget *> &out) {
    for (int i = 0; i < layout->count(); ++i) {
        QLayoutItem *item = layout->itemAt(i);
        if (QWidget *w = item->widget())
            out.append(w);
        else if (QLayout *inner = item->layout())
            placedWidgets(inner, out);
    }
}

bool seen(const QWidget *w) {
    return w->isVisible() && !w->visibleRegion().isEmpty();
}

} // namespace

QStringList screenProblems(QWidget &top) {
    QStringList problems;
    QList<QWidget *> all = top.findChildren<QWidget *>();
    all.prepend(&top);
    for (QWidget *w : std::as_const(all)) {
        if (!seen(w))
            continue;
        if (const QString why = clippedText(w); !why.isEmpty())
            problems.append(QStringLiteral("%1: %2").arg(widgetName(w), why));
        if (auto *scroll = qobject_cast<QScrollArea *>(w);
            scroll && scroll->horizontalScrollBar()->isVisible())
            problems.append(QStringLiteral("%1: needs a horizontal scroll bar (%2 px more)")
                                .arg(widgetName(w))
                                .arg(scroll->horizontalScrollBar()->maximum()));
        // Two widgets one layout places side by side must not cover each other: a layout
        // squeezed below its minimum piles them up.
        if (QLayout *layout = w->layout()) {
            QList<QWidget *> placed;
            placedWidgets(layout, placed);
            placed.removeIf([](const QWidget *p) { return !seen(p); });
            for (qsizetype i = 0; i < placed.size(); ++i)
                for (qsizetype j = i + 1; j < placed.size(); ++j) {
                    const QRect a = placed.at(i)->geometry().adjusted(1, 1, -1, -1);
                    const QRect b = placed.at(j)->geometry().adjusted(1, 1, -1, -1);
                    if (a.intersects(b))
                        problems.append(QStringLiteral("%1 and %2 overlap in %3")
                                            .arg(widgetName(placed.at(i)), widgetName(placed.at(j)),
                                                 widgetName(w)));
                }
        }
    }
    problems.removeDuplicates();
    return problems;
}

} // namespace tipscope::testing
