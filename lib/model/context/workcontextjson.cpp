#include "model/context/workcontextjson.h"

#include "base/elide.h"

#include <QCoreApplication>
#include <utility>

namespace tipscope::model {

namespace {
struct WorkContextJsonTr {
    Q_DECLARE_TR_FUNCTIONS(WorkContextJson)
};

const QString kWorkOrder = QStringLiteral("work_order");
const QString kSerial = QStringLiteral("board_serial");
const QString kOperator = QStringLiteral("operator");
QString fieldProblem(const QString &key, const QString &text) {
    if (text.size() > kMaxWorkContextChars)
        return WorkContextJsonTr::tr("%1 has %2 characters; at most %3 are kept")
            .arg(key)
            .arg(text.size())
            .arg(kMaxWorkContextChars);
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c.category() == QChar::Other_Control || c.category() == QChar::Other_Format)
            return WorkContextJsonTr::tr("%1 holds a control character (%2) at character %3")
                .arg(key, base::elided(QString(c)))
                .arg(i + 1);
    }
    return {};
}
} // namespace

QString workContextProblem(const WorkContext &context) {
    for (const auto &[key, text] :
         {std::pair{kWorkOrder, context.workOrder}, std::pair{kSerial, context.boardSerial},
          std::pair{kOperator, context.operatorName}})
        if (const QString why = fieldProblem(key, text); !why.isEmpty())
            return why;
    return {};
}

QJsonObject workContextToJson(const WorkContext &context) {
    return {{kWorkOrder, context.workOrder},
            {kSerial, context.boardSerial},
            {kOperator, context.operatorName}};
}

base::Outcome<WorkContext> workContextFromJson(const QJsonObject &json) {
    for (const QString &key : {kWorkOrder, kSerial, kOperator})
        if (json.contains(key) && !json.value(key).isString())
            return base::failure(WorkContextJsonTr::tr("%1 must be text").arg(key));
    const WorkContext context{json.value(kWorkOrder).toString().trimmed(),
                              json.value(kSerial).toString().trimmed(),
                              json.value(kOperator).toString().trimmed()};
    if (const QString why = workContextProblem(context); !why.isEmpty())
        return base::failure(why);
    return context;
}

} // namespace tipscope::model
