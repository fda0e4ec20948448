// The Qt and standard headers that most translation units of lib/ and app/ include, compiled
// once per configuration and reused by every target (see "Precompiled headers" in
// docs/development.md). Only headers that never change go here: a project header would make
// every change to it rebuild everything, and a module header (<QtCore>) costs more to load than
// it saves.
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QLocale>
#include <QLoggingCategory>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>
